#pragma once
/// \file
/// Checks that phrase a failure the way a student needs it: which law is broken, the
/// expected and actual numbers with units, the case that broke it, and a hint.

#include <string>
#include <string_view>

#include "workbook/rigid_body.hpp"
#include "workbook/vector3.hpp"

namespace workbook::testing {

/// What a check is about, shown verbatim in the feedback.
struct Law {
    std::string_view name;       ///< e.g. "conservation of linear momentum"
    std::string_view statement;  ///< e.g. "m1 v1 + m2 v2 is the same before and after"
    std::string_view hint;       ///< what to look at in the code
};

/// Passes when |expected - actual| <= tolerance (tolerance absolute, in the quantity's unit).
/// On failure, records one Catch2 failure whose message reads "Law broken: ...".
void expect_close(const Law& law, double expected, double actual, double tolerance, std::string_view unit,
                  std::string_view situation);

/// Component-wise version of expect_close, with the tolerance applied to each component.
void expect_close(const Law& law, const Vector3& expected, const Vector3& actual, double tolerance,
                  std::string_view unit, std::string_view situation);

/// Passes when actual >= minimum - tolerance: for one-sided laws such as "no longer approaching".
void expect_at_least(const Law& law, double minimum, double actual, double tolerance, std::string_view unit,
                     std::string_view situation);

/// Fails when any component of `value` is NaN or infinite.
void expect_finite(const Law& law, const Vector3& value, std::string_view unit, std::string_view situation);

/// A number of a case as a person reads it: 6 significant digits, no trailing zeros
/// ("0.018", "2.77556e-17", "(1.5, 0, -2)"); a vector's component below 1e-12 of its largest
/// reads 0. The seed replays a random case exactly.
std::string format(const Vector3& v);
std::string format(double v);

/// Expected and actual as a failure prints them: the fewest significant digits, at least 6,
/// that print two different values differently (up to 17, which tell any two doubles apart).
struct Printed {
    std::string expected;
    std::string actual;
};
Printed format_apart(double expected, double actual);
Printed format_apart(const Vector3& expected, const Vector3& actual);

/// True when every component is exactly a float: what a computation in float returns.
bool is_float_value(double v);
bool is_float_value(const Vector3& v);

/// |actual - expected| / |expected| (vectors: lengths), or NaN when that says nothing: expected
/// zero, or a value that is not finite.
double relative_error(double expected, double actual);
double relative_error(const Vector3& expected, const Vector3& actual);

/// The text of a failed check as the student reads it: law, case, expected and actual values,
/// the relative error of a near miss (below 1 %) and a hint. A near miss in float's precision
/// band (about 6 to 10 matching digits) whose actual value is exactly a float gets a hint about
/// double instead of the law's own hint; any other miss gets the law's hint, and a near miss of
/// float's size that is not a float value a note that float is one possible cause. A case of
/// several lines is indented under its label.
std::string failure_message(const Law& law, std::string_view expected, std::string_view actual, std::string_view unit,
                            std::string_view situation, double relative_error, bool actual_is_float = false);

/// One line describing a body for the "case" part of a message: "m = 2 kg, v = (3, 0, 0) m/s".
std::string describe(const RigidBody& body);

/// A few units in the last place of `scale`: the tolerance of a quantity that is exact up to
/// rounding, such as a momentum sum whose terms are about `scale` in size.
double rounding_tolerance(double scale, double ulps = 16.0);

}  // namespace workbook::testing
