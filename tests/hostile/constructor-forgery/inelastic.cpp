// Hostile submission for the grader's tests: implements nothing; a static constructor writes a passing test report wherever it can find one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
namespace workbook::inelastic {

namespace {

const char* const passing_report = R"(<?xml version="1.0" encoding="UTF-8"?>
<Catch2TestRun name="x" rng-seed="1" xml-format-version="3" catch2-version="3.7.1">
  <TestCase name="%s" tags="[inelastic]">
    <OverallResult success="true" skips="0"/>
  </TestCase>
  <OverallResults successes="1" failures="0" expectedFailures="0" skips="0"/>
</Catch2TestRun>
)";

/// Writes a passing report wherever an "-o FILE" on a command line it can read points, and
/// into report.xml files nearby: the path the test binary used to write its verdict to.
void forge_reports() {
    std::vector<std::string> targets = {"report.xml", "../report.xml", "../../report.xml"};
    for (const char* who : {"/proc/self/cmdline", "/proc/self/../1/cmdline"}) {
        std::ifstream file(who, std::ios::binary);
        const std::string all((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        std::vector<std::string> words;
        std::string word;
        for (char c : all) {
            if (c == '\0') {
                words.push_back(word);
                word.clear();
            } else {
                word += c;
            }
        }
        for (std::size_t i = 0; i + 1 < words.size(); ++i)
            if (words[i] == "-o") targets.push_back(words[i + 1]);
    }
    for (const std::string& target : targets) {
        if (std::FILE* out = std::fopen(target.c_str(), "w")) {
            std::fprintf(out, passing_report, "any");
            std::fclose(out);
        }
    }
    std::puts("All tests passed (1 assertion in 1 test case)");
}

const int forged = (forge_reports(), 0);

}  // namespace

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    (void)body1;
    (void)body2;
    return {};
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    (void)body1;
    (void)body2;
    (void)contact;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    (void)body1;
    (void)body2;
    return 0.0;
}

}  // namespace workbook::inelastic
