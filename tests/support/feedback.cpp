#include "feedback.hpp"

#include <catch2/catch_test_macros.hpp>
#include <fmt/core.h>

#include <cmath>
#include <limits>

namespace workbook::testing {

namespace {

bool close(double expected, double actual, double tolerance) {
    return std::isfinite(actual) && std::abs(expected - actual) <= tolerance;
}

void report(const Law& law, const std::string& expected, const std::string& actual, std::string_view unit,
            std::string_view situation) {
    FAIL_CHECK(fmt::format("Law broken: {} ({}).\n  case:     {}\n  expected: {} {}\n  actual:   {} {}\n  hint:     {}",
                           law.name, law.statement, situation, expected, unit, actual, unit, law.hint));
}

}  // namespace

std::string format(double v) { return fmt::format("{:.10g}", v); }

std::string format(const Vector3& v) { return fmt::format("({}, {}, {})", format(v.x), format(v.y), format(v.z)); }

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
    report(law, format(expected), format(actual), unit, situation);
}

void expect_close(const Law& law, const Vector3& expected, const Vector3& actual, double tolerance,
                  std::string_view unit, std::string_view situation) {
    if (close(expected.x, actual.x, tolerance) && close(expected.y, actual.y, tolerance) &&
        close(expected.z, actual.z, tolerance)) {
        SUCCEED();
        return;
    }
    report(law, format(expected), format(actual), unit, situation);
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
