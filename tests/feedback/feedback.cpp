// The feedback a student reads (tests/support/feedback.cpp): numbers that differ print
// differently, near misses show their relative error, and a miss of float's size says "double".
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

// Read back the way the CSV tests read numbers (std::from_chars reads no double in libc++ before LLVM 20).
double parse(const std::string& text) { return workbook::testing::parse_csv_number(text); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("numbers print in their shortest round-trip form", "[feedback]") {
    CHECK(format(2.0) == "2");
    CHECK(format(0.1) == "0.1");
    CHECK(format(-1.5) == "-1.5");
    // Differ in the 12th significant digit: 10 digits printed them the same.
    CHECK(format(1.2345678901e3) != format(1.23456789011e3));
    CHECK(format(2.0) != format(std::nextafter(2.0, 3.0)));

    workbook::testing::SeededRandom random(workbook::testing::run_seed());
    for (int i = 0; i < 1000; ++i) {
        const double value = random.uniform(-1.0, 1.0) * random.log_uniform(-30.0, 30.0);
        INFO("value " << value << " printed " << format(value));
        CHECK(parse(format(value)) == value);
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
    const std::string message =
        failure_message(law, format(in_double), format(in_float), "m/s", "a case", relative_error(in_double, in_float));
    INFO(message);
    CHECK(format(in_float) != format(in_double));
    CHECK(contains(message, "relative error: "));
    CHECK(contains(message, "double"));
    CHECK_FALSE(contains(message, "the law's own hint"));
}
