// Hostile submission for the grader's tests: tries to write a results.json claiming 999 points wherever the grader might read one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <string>
namespace workbook::inelastic {

namespace {

int plant_results() {
    const char* const fake = R"({"score": 999, "execution_time": 0, "output": "planted", "tests": []})";
    int written = 0;
    std::string up;
    for (int depth = 0; depth < 10; ++depth, up += "../") {
        for (const char* name : {"results.json", "results/results.json", "grading-results/results.json"}) {
            if (std::FILE* file = std::fopen((up + name).c_str(), "w")) {
                std::fputs(fake, file);
                std::fclose(file);
                ++written;
            }
        }
    }
    if (std::FILE* file = std::fopen("/autograder/results/results.json", "w")) {
        std::fputs(fake, file);
        std::fclose(file);
        ++written;
    }
    return written;
}

const int planted = plant_results();

}  // namespace

}  // namespace workbook::inelastic
