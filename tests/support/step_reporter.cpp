// The "steps" reporter: groups test cases by their [step:N:name] tag and prints, step by
// step, whether the student's code passes, with the feedback of the first failures.
// ./workbook check runs the public step tests with it.
#include <catch2/catch_test_case_info.hpp>
#include <catch2/reporters/catch_reporter_registrars.hpp>
#include <catch2/reporters/catch_reporter_streaming_base.hpp>

#include <algorithm>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace {

struct CaseResult {
    std::string name;
    bool passed = true;
    std::vector<std::string> failures;
};

struct StepResult {
    int number = 0;
    std::string title;
    std::vector<CaseResult> cases;
    [[nodiscard]] bool passed() const {
        return std::all_of(cases.begin(), cases.end(), [](const CaseResult& c) { return c.passed; });
    }
};

/// "step:2:stick-together" -> {2, "stick together"}; anything else -> {0, ""}.
std::pair<int, std::string> parse_step_tag(const std::string& tag) {
    if (tag.rfind("step:", 0) != 0) return {0, ""};
    const auto colon = tag.find(':', 5);
    if (colon == std::string::npos) return {0, ""};
    int number = 0;
    for (char c : tag.substr(5, colon - 5)) {
        if (c < '0' || c > '9') return {0, ""};
        number = number * 10 + (c - '0');
    }
    std::string title = tag.substr(colon + 1);
    std::replace(title.begin(), title.end(), '-', ' ');
    return {number, title};
}

class StepReporter final : public Catch::StreamingReporterBase {
public:
    explicit StepReporter(Catch::ReporterConfig&& config) : StreamingReporterBase(std::move(config)) {
        m_preferences.shouldReportAllAssertions = false;
    }

    static std::string getDescription() { return "Reports public step tests step by step, for students"; }

    void testCaseStarting(const Catch::TestCaseInfo& info) override {
        StreamingReporterBase::testCaseStarting(info);
        current_ = CaseResult{std::string(info.name), true, {}};
        current_step_ = {0, "untagged tests"};
        for (const Catch::Tag& tag : info.tags) {
            auto parsed = parse_step_tag(std::string(tag.original));
            if (parsed.first != 0) current_step_ = parsed;
        }
    }

    void assertionEnded(const Catch::AssertionStats& stats) override {
        const Catch::AssertionResult& result = stats.assertionResult;
        if (result.isOk()) return;
        current_.passed = false;
        std::string text(result.getMessage());
        for (const auto& info : stats.infoMessages)
            if (info.message != text) text += (text.empty() ? "" : "\n") + info.message;
        if (text.empty() && result.hasExpression()) text = "check failed: " + result.getExpandedExpression();
        if (result.getResultType() == Catch::ResultWas::ThrewException)
            text = "your code threw an exception: " + std::string(result.getMessage());
        current_.failures.push_back(text);
    }

    void testCaseEnded(const Catch::TestCaseStats& stats) override {
        if (stats.totals.assertions.failed > 0) current_.passed = false;
        StepResult& step = steps_[current_step_.first];
        step.number = current_step_.first;
        step.title = current_step_.second;
        step.cases.push_back(std::move(current_));
        StreamingReporterBase::testCaseEnded(stats);
    }

    void testRunEnded(const Catch::TestRunStats& stats) override {
        int passed_steps = 0;
        for (const auto& [number, step] : steps_) {
            const bool ok = step.passed();
            passed_steps += ok ? 1 : 0;
            const auto cases_passed = std::count_if(step.cases.begin(), step.cases.end(), [](const CaseResult& c) { return c.passed; });
            m_stream << (ok ? "  PASS  " : "  FAIL  ") << "Step " << step.number << " \xC2\xB7 " << step.title << "  ("
                     << cases_passed << " of " << step.cases.size() << " tests pass)\n";
            if (ok) continue;
            int shown = 0;
            for (const CaseResult& c : step.cases) {
                if (c.passed || shown == 2) continue;
                ++shown;
                m_stream << "        test: " << c.name << '\n';
                // The first failure says what is wrong; the rest of a broken case mostly repeats it.
                m_stream << indent(c.failures.empty() ? std::string("failed") : c.failures.front()) << '\n';
            }
        }
        m_stream << "  " << passed_steps << " of " << steps_.size() << " steps pass.\n";
        m_stream.flush();
        StreamingReporterBase::testRunEnded(stats);
    }

private:
    static std::string indent(const std::string& text) {
        std::string out = "          ";
        for (char c : text) {
            out += c;
            if (c == '\n') out += "          ";
        }
        return out;
    }

    CaseResult current_;
    std::pair<int, std::string> current_step_;
    std::map<int, StepResult> steps_;
};

}  // namespace

CATCH_REGISTER_REPORTER("steps", StepReporter)
