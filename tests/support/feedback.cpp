#include "feedback.hpp"

#include <catch2/catch_test_macros.hpp>
#include <fmt/core.h>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace workbook::testing {

namespace {

bool close(double expected, double actual, double tolerance) {
    return std::isfinite(actual) && std::abs(expected - actual) <= tolerance;
}

// A miss of less than 1 % is a near miss: the relative error tells more than the digits.
constexpr double near_miss = 1e-2;
// float keeps 24 bits (about 7 digits); a double computation misses by far less than 1e-10,
// a float one by about 1e-8 to 1e-6.
constexpr double float_band_low = 1e-10;
constexpr double float_band_high = 1e-5;

void report(const Law& law, const std::string& expected, const std::string& actual, std::string_view unit,
            std::string_view situation, double relative = std::numeric_limits<double>::quiet_NaN()) {
    FAIL_CHECK(failure_message(law, expected, actual, unit, situation, relative));
}

}  // namespace

std::string failure_message(const Law& law, std::string_view expected, std::string_view actual, std::string_view unit,
                            std::string_view situation, double relative_error) {
    std::string text = fmt::format("Law broken: {} ({}).\n  case:     {}\n  expected: {} {}\n  actual:   {} {}", law.name,
                                   law.statement, situation, expected, unit, actual, unit);
    const bool near = std::isfinite(relative_error) && relative_error > 0.0 && relative_error < near_miss;
    if (near) text += fmt::format("\n  relative error: {:.2g}", relative_error);
    if (near && relative_error >= float_band_low && relative_error < float_band_high) {
        const int digits = static_cast<int>(std::floor(-std::log10(relative_error)));
        text += fmt::format(
            "\n  hint:     the values agree to only about {} significant digits, what a float holds: compute in "
            "double throughout (a float variable, a float parameter or a literal such as 0.5f keeps about 7 digits)",
            digits);
    } else {
        text += fmt::format("\n  hint:     {}", law.hint);
    }
    return text;
}

std::string format(double v) {
    std::array<char, 64> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
    if (error != std::errc{}) return fmt::format("{}", v);
    return std::string(buffer.data(), end);
}

std::string format(const Vector3& v) { return fmt::format("({}, {}, {})", format(v.x), format(v.y), format(v.z)); }

double relative_error(double expected, double actual) {
    if (!std::isfinite(expected) || !std::isfinite(actual) || expected == 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    return std::abs(actual - expected) / std::abs(expected);
}

double relative_error(const Vector3& expected, const Vector3& actual) {
    if (!is_finite(expected) || !is_finite(actual) || length(expected) == 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    return length(actual - expected) / length(expected);
}

std::string describe(const RigidBody& body) {
    const std::string mass = body.is_immovable() ? std::string("immovable") : "m = " + format(body.mass()) + " kg";
    return fmt::format("{}, v = {} m/s", mass, format(body.velocity));
}

double rounding_tolerance(double scale, double ulps) {
    return ulps * std::numeric_limits<double>::epsilon() * std::max(std::abs(scale), std::numeric_limits<double>::min());
}

void expect_close(const Law& law, double expected, double actual, double tolerance, std::string_view unit,
                  std::string_view situation) {
    if (close(expected, actual, tolerance)) {
        SUCCEED();
        return;
    }
    report(law, format(expected), format(actual), unit, situation, relative_error(expected, actual));
}

void expect_close(const Law& law, const Vector3& expected, const Vector3& actual, double tolerance,
                  std::string_view unit, std::string_view situation) {
    if (close(expected.x, actual.x, tolerance) && close(expected.y, actual.y, tolerance) &&
        close(expected.z, actual.z, tolerance)) {
        SUCCEED();
        return;
    }
    report(law, format(expected), format(actual), unit, situation, relative_error(expected, actual));
}

void expect_at_least(const Law& law, double minimum, double actual, double tolerance, std::string_view unit,
                     std::string_view situation) {
    if (std::isfinite(actual) && actual >= minimum - tolerance) {
        SUCCEED();
        return;
    }
    report(law, "at least " + format(minimum), format(actual), unit, situation);
}

void expect_finite(const Law& law, const Vector3& value, std::string_view unit, std::string_view situation) {
    if (is_finite(value)) {
        SUCCEED();
        return;
    }
    report(law, "finite numbers", format(value), unit, situation);
}

}  // namespace workbook::testing
