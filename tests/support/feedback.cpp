#include "feedback.hpp"

#include <catch2/catch_test_macros.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

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
            std::string_view situation, double relative = std::numeric_limits<double>::quiet_NaN(),
            bool actual_is_float = false) {
    FAIL_CHECK(failure_message(law, expected, actual, unit, situation, relative, actual_is_float));
}

// The label column of a message ("  expected: "): a case of several lines is indented to it.
constexpr std::string_view label_indent = "\n            ";

std::string indented(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '\n')
            out += label_indent;
        else
            out += c;
    }
    return out;
}

std::string with_digits(double v, int digits) {
    if (v == 0.0) return std::signbit(v) ? "-0" : "0";
    return fmt::format("{:.{}g}", v, digits);
}

constexpr int fewest_digits = 6;
constexpr int round_trip_digits = 17;

}  // namespace

std::string failure_message(const Law& law, std::string_view expected, std::string_view actual, std::string_view unit,
                            std::string_view situation, double relative_error, bool actual_is_float) {
    std::string text = fmt::format("Law broken: {} ({}).\n  case:     {}\n  expected: {} {}\n  actual:   {} {}", law.name,
                                   law.statement, indented(situation), expected, unit, actual, unit);
    const bool near = std::isfinite(relative_error) && relative_error > 0.0 && relative_error < near_miss;
    if (near) text += fmt::format("\n  relative error: {:.2g}", relative_error);
    // A near miss of float's size is float's doing for sure when the value checked is itself a
    // float (what a function computing in float returns): then the hint says double. A value
    // derived from one (a momentum m v) or a double computation that stopped early (a loop
    // with a low cap) misses by as much without being a float: the law's own hint comes first,
    // and a note says what else so few digits can mean.
    const bool float_sized = near && relative_error >= float_band_low && relative_error < float_band_high;
    const int digits = float_sized ? static_cast<int>(std::floor(-std::log10(relative_error))) : 0;
    if (float_sized && actual_is_float) {
        text += fmt::format(
            "\n  hint:     the values agree to only about {} significant digits, what a float holds: compute in "
            "double throughout (a float variable, a float parameter or a literal such as 0.5f keeps about 7 digits)",
            digits);
    } else {
        text += fmt::format("\n  hint:     {}", law.hint);
        if (float_sized)
            text += fmt::format(
                "\n  note:     about {} significant digits agree, also what a float keeps: if a variable, a parameter "
                "or a literal such as 0.5f is a float, compute in double",
                digits);
    }
    return text;
}

std::string format(double v) {
    if (!std::isfinite(v)) return fmt::format("{}", v);
    return with_digits(v, fewest_digits);
}

std::string format(const Vector3& v) {
    // A component a trillion times smaller than the largest is rounding left by a rotation or a
    // sum (2.77556e-17 beside 0.433): a case reads it as the 0 it stands for.
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const auto one = [largest](double c) { return std::abs(c) < 1e-12 * largest ? std::string("0") : format(c); };
    return fmt::format("({}, {}, {})", one(v.x), one(v.y), one(v.z));
}

Printed format_apart(double expected, double actual) {
    int digits = fewest_digits;
    while (digits < round_trip_digits && expected != actual && with_digits(expected, digits) == with_digits(actual, digits))
        ++digits;
    if (!std::isfinite(expected) || !std::isfinite(actual)) digits = fewest_digits;
    return {std::isfinite(expected) ? with_digits(expected, digits) : fmt::format("{}", expected),
            std::isfinite(actual) ? with_digits(actual, digits) : fmt::format("{}", actual)};
}

Printed format_apart(const Vector3& expected, const Vector3& actual) {
    // One number of digits for every component, enough for the component that needs most.
    int digits = fewest_digits;
    const std::array<std::pair<double, double>, 3> pairs{{{expected.x, actual.x}, {expected.y, actual.y}, {expected.z, actual.z}}};
    for (const auto& [e, a] : pairs) {
        if (!std::isfinite(e) || !std::isfinite(a)) continue;
        while (digits < round_trip_digits && e != a && with_digits(e, digits) == with_digits(a, digits)) ++digits;
    }
    const auto one = [digits](double v) { return std::isfinite(v) ? with_digits(v, digits) : fmt::format("{}", v); };
    return {fmt::format("({}, {}, {})", one(expected.x), one(expected.y), one(expected.z)),
            fmt::format("({}, {}, {})", one(actual.x), one(actual.y), one(actual.z))};
}

bool is_float_value(double v) {
    return std::isfinite(v) && std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max()) &&
           static_cast<double>(static_cast<float>(v)) == v;
}

bool is_float_value(const Vector3& v) { return is_float_value(v.x) && is_float_value(v.y) && is_float_value(v.z); }

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
    const Printed printed = format_apart(expected, actual);
    report(law, printed.expected, printed.actual, unit, situation, relative_error(expected, actual), is_float_value(actual));
}

void expect_close(const Law& law, const Vector3& expected, const Vector3& actual, double tolerance,
                  std::string_view unit, std::string_view situation) {
    if (close(expected.x, actual.x, tolerance) && close(expected.y, actual.y, tolerance) &&
        close(expected.z, actual.z, tolerance)) {
        SUCCEED();
        return;
    }
    const Printed printed = format_apart(expected, actual);
    report(law, printed.expected, printed.actual, unit, situation, relative_error(expected, actual), is_float_value(actual));
}

void expect_at_least(const Law& law, double minimum, double actual, double tolerance, std::string_view unit,
                     std::string_view situation) {
    if (std::isfinite(actual) && actual >= minimum - tolerance) {
        SUCCEED();
        return;
    }
    const Printed printed = format_apart(minimum, actual);
    report(law, "at least " + printed.expected, printed.actual, unit, situation);
}

void expect_finite(const Law& law, const Vector3& value, std::string_view unit, std::string_view situation) {
    if (is_finite(value)) {
        SUCCEED();
        return;
    }
    report(law, "finite numbers", format(value), unit, situation);
}

}  // namespace workbook::testing
