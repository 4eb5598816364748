// The feedback a student reads (tests/support/feedback.cpp): a case in 6 digits, expected and
// actual with the fewest digits that tell them apart, near misses with their relative error, and
// "double" only for a value that is a float.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>

#include "csv_table.hpp"
#include "feedback.hpp"
#include "seeded_random.hpp"

using namespace workbook;
using workbook::testing::failure_message;
using workbook::testing::format;
using workbook::testing::Law;
using workbook::testing::relative_error;

namespace {

const Law law{"a law", "its statement", "the law's own hint"};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a case prints its numbers with 6 significant digits", "[feedback]") {
    CHECK(format(2.0) == "2");
    CHECK(format(0.1) == "0.1");
    CHECK(format(-1.5) == "-1.5");
    CHECK(format(0.018000000000000016) == "0.018");
    CHECK(format(2.7755575615628914e-17) == "2.77556e-17");
    CHECK(format(Vector3{1.0 / 3.0, 0, -2}) == "(0.333333, 0, -2)");
    CHECK(format(Vector3{-0.4330127018922193, 0, 2.7755575615628914e-17}) == "(-0.433013, 0, 0)");
    CHECK(format(Vector3{0, 0, 2.7755575615628914e-17}) == "(0, 0, 2.77556e-17)");
}

TEST_CASE("expected and actual print with the fewest digits that tell them apart, at least 6", "[feedback]") {
    const auto apart = workbook::testing::format_apart(0.018, 0.018000000000000016);
    CHECK(apart.expected != apart.actual);
    CHECK(apart.expected == "0.018");
    CHECK(apart.actual == "0.01800000000000002");
    const auto far = workbook::testing::format_apart(6.055555555555555, 0.0);
    CHECK(far.expected == "6.05556");
    CHECK(far.actual == "0");
    const auto tiny = workbook::testing::format_apart(0.0, 2.7755575615628914e-17);
    CHECK(tiny.actual == "2.77556e-17");
    // Differ in the 12th significant digit: 12 digits are printed, for both.
    const auto twelfth = workbook::testing::format_apart(1.2345678901e3, 1.23456789011e3);
    CHECK(twelfth.expected == "1234.5678901");
    CHECK(twelfth.actual == "1234.56789011");
    const auto vectors = workbook::testing::format_apart(Vector3{1, 2, 3}, Vector3{1, 2, std::nextafter(3.0, 4.0)});
    CHECK(vectors.expected != vectors.actual);

    workbook::testing::SeededRandom random(workbook::testing::run_seed());
    for (int i = 0; i < 1000; ++i) {
        const double sign_and_size = random.uniform(-1.0, 1.0);
        const double value = sign_and_size * random.log_uniform(-30.0, 30.0);
        const double next = std::nextafter(value, 2.0 * value);
        const auto printed = workbook::testing::format_apart(value, next);
        INFO("value " << value << " printed " << printed.expected << " and " << printed.actual);
        CHECK(printed.expected != printed.actual);
    }
}

TEST_CASE("a near miss shows its relative error, a far miss does not", "[feedback]") {
    CHECK(relative_error(2.0, 2.002) == Catch::Approx(1e-3));
    CHECK(std::isnan(relative_error(0.0, 1.0)));
    CHECK(std::isnan(relative_error(1.0, std::nan(""))));
    CHECK(relative_error(Vector3{3, 4, 0}, Vector3{3, 4, 0.005}) == Catch::Approx(1e-3));

    const std::string near = failure_message(law, "2", "2.002", "m/s", "a case", relative_error(2.0, 2.002));
    CHECK(contains(near, "relative error: 0.001"));
    CHECK(contains(near, "hint:     the law's own hint"));

    const std::string far = failure_message(law, "2", "3", "m/s", "a case", relative_error(2.0, 3.0));
    CHECK_FALSE(contains(far, "relative error"));
    CHECK(contains(far, "the law's own hint"));
}

TEST_CASE("a float computation gets a hint that says double", "[feedback]") {
    // Step 1's common velocity of a 0.25 kg and a 3 kg body, computed in float as a student
    // who declared float variables would.
    const float w1 = 1.0f / 0.25f;
    const float w2 = 1.0f / 3.0f;
    const float v1 = 4.0f;
    const float v2 = -1.0f;
    const double in_float = static_cast<double>((w2 * v1 + w1 * v2) / (w1 + w2));
    const double in_double = ((1.0 / 3.0) * 4.0 + 4.0 * -1.0) / (4.0 + 1.0 / 3.0);
    REQUIRE(in_float != in_double);
    const auto printed = workbook::testing::format_apart(in_double, in_float);
    const std::string message = failure_message(law, printed.expected, printed.actual, "m/s", "a case",
                                                relative_error(in_double, in_float), workbook::testing::is_float_value(in_float));
    INFO(message);
    CHECK(printed.expected != printed.actual);
    CHECK(contains(message, "relative error: "));
    CHECK(contains(message, "double"));
    CHECK_FALSE(contains(message, "the law's own hint"));
}

TEST_CASE("a double computation that misses by as much gets the law's own hint first", "[feedback]") {
    // A loop stopped a few passes early misses by about 2e-6 in double (chapter 4, four sweeps).
    const double expected = 1.0 / 3.0;
    const double actual = expected * (1.0 + 2.1e-6);
    REQUIRE_FALSE(workbook::testing::is_float_value(actual));
    const auto printed = workbook::testing::format_apart(expected, actual);
    const std::string message = failure_message(law, printed.expected, printed.actual, "m/s", "a case",
                                                relative_error(expected, actual), workbook::testing::is_float_value(actual));
    INFO(message);
    CHECK(contains(message, "relative error: "));
    CHECK(contains(message, "hint:     the law's own hint\n  note:     about 5 significant digits agree, also what a float keeps"));
    CHECK_FALSE(contains(message, "what a float holds: compute in double throughout"));
}

TEST_CASE("a case of several lines is indented under its label", "[feedback]") {
    const std::string message = failure_message(law, "1", "2", "m", "body 1: here\nbody 2: there", 0.5);
    CHECK(contains(message, "  case:     body 1: here\n            body 2: there\n  expected: 1 m"));
}
