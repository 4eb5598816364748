// Vector3, Matrix3 and Quaternion against identities that hold exactly. Small integer
// inputs keep every product and sum exact in double precision, so those checks use ==;
// the rest allow a few units in the last place of the quantity's scale.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "checks.hpp"
#include "seeded_random.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/quaternion.hpp"
#include "workbook/vector3.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const Vector3 a{1, 2, 3};
const Vector3 b{4, -5, 6};

/// The same rotation as to_matrix, derived independently: q (0, v) q*.
Vector3 rotate_by_sandwich(const Quaternion& q, const Vector3& v) {
    const Quaternion r = q * Quaternion{0.0, v.x, v.y, v.z} * conjugate(q);
    return {r.x, r.y, r.z};
}

/// The signed angle, in (-2 pi, 2 pi], of a unit quaternion that rotates about `axis`.
double angle_about(const Quaternion& q, const Vector3& axis) { return 2.0 * std::atan2(dot({q.x, q.y, q.z}, axis), q.w); }

}  // namespace

TEST_CASE("dot and cross of two integer vectors", "[math][vector]") {
    CHECK(dot(a, b) == 12.0);
    CHECK(cross(a, b) == Vector3{27, 6, -13});
    CHECK(length_squared(a) == 14.0);
    CHECK(length(Vector3{2, 3, 6}) == 7.0);
}

TEST_CASE("the cross product follows the right-hand rule on the axes", "[math][vector]") {
    const Vector3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    CHECK(cross(x, y) == z);
    CHECK(cross(y, z) == x);
    CHECK(cross(z, x) == y);
    CHECK(cross(x, x) == Vector3{});
}

TEST_CASE("cross is anticommutative and orthogonal to both factors", "[math][vector]") {
    CHECK(cross(a, b) == -cross(b, a));
    CHECK(dot(a, cross(a, b)) == 0.0);
    CHECK(dot(b, cross(a, b)) == 0.0);
}

TEST_CASE("Lagrange identity |a x b|^2 = |a|^2 |b|^2 - (a . b)^2", "[math][vector]") {
    // 14 * 77 - 144: exact for integers.
    CHECK(length_squared(cross(a, b)) == 934.0);
    CHECK(length_squared(cross(a, b)) == length_squared(a) * length_squared(b) - dot(a, b) * dot(a, b));

    // For general values both sides round; the error is a few ulps of |a|^2 |b|^2.
    workbook::testing::SeededRandom random(workbook::testing::run_seed());
    for (int i = 0; i < 200; ++i) {
        const Vector3 u = random.vector(10.0);
        const Vector3 v = random.vector(10.0);
        const double scale = length_squared(u) * length_squared(v);
        CAPTURE(u, v);
        CHECK_THAT(length_squared(cross(u, v)), WithinAbs(scale - dot(u, v) * dot(u, v), 16 * eps * scale));
        CHECK_THAT(dot(u, cross(u, v)), WithinAbs(0.0, 16 * eps * length(u) * length(u) * length(v)));
    }
}

TEST_CASE("normalized gives a unit vector along the input", "[math][vector]") {
    CHECK(normalized(Vector3{0, 3, 4}) == Vector3{0, 0.6, 0.8});
    CHECK(is_finite(Vector3{1, 2, 3}));
    CHECK_FALSE(is_finite(Vector3{1, std::numeric_limits<double>::infinity(), 3}));
    CHECK_FALSE(is_finite(Vector3{std::numeric_limits<double>::quiet_NaN(), 0, 0}));
}

TEST_CASE("determinant of a known matrix and of a product", "[math][matrix]") {
    const Matrix3 m{{2, -1, 0, 1, 3, 2, 0, 1, 4}};
    const Matrix3 n{{1, 2, 0, 0, 1, -3, 2, 0, 1}};
    CHECK(determinant(m) == 24.0);
    CHECK(determinant(n) == -11.0);
    CHECK(determinant(m * n) == 24.0 * -11.0);
    CHECK(determinant(transpose(m)) == 24.0);
    CHECK(determinant(Matrix3::identity()) == 1.0);
    CHECK(determinant(Matrix3::diagonal({2, 3, 5})) == 30.0);
}

TEST_CASE("matrix-vector and matrix-matrix products", "[math][matrix]") {
    const Matrix3 m{{2, -1, 0, 1, 3, 2, 0, 1, 4}};
    CHECK(m * Vector3{1, 2, 3} == Vector3{0, 13, 14});
    CHECK(m * Matrix3::identity() == m);
    CHECK(Matrix3::identity() * m == m);
    CHECK(m * 2.0 + m == m * 3.0);
    CHECK(m(1, 2) == 2.0);
    CHECK(m.row(2) == Vector3{0, 1, 4});
    CHECK(m.column(0) == Vector3{2, 1, 0});
}

TEST_CASE("the transpose of a product is the product of the transposes, reversed", "[math][matrix]") {
    const Matrix3 m{{2, -1, 0, 1, 3, 2, 0, 1, 4}};
    const Matrix3 n{{1, 2, 0, 0, 1, -3, 2, 0, 1}};
    CHECK(transpose(m * n) == transpose(n) * transpose(m));
    CHECK(transpose(transpose(m)) == m);
    CHECK(transpose(m)(0, 1) == m(1, 0));
}

TEST_CASE("inverse is the adjugate over the determinant and undoes the matrix", "[math][matrix]") {
    const Matrix3 m{{2, -1, 0, 1, 3, 2, 0, 1, 4}};
    const Matrix3 adjugate{{10, 4, -2, -4, 8, -4, 1, -2, 7}};
    const Matrix3 inv = inverse(m);
    // Each entry is an integer times 1/24, rounded once or twice.
    CHECK_THAT(inv, is_close_to(adjugate * (1.0 / 24.0), 2 * eps));
    CHECK_THAT(inv * m, is_close_to(Matrix3::identity(), 4 * eps));
    CHECK_THAT(m * inv, is_close_to(Matrix3::identity(), 4 * eps));
    CHECK(inverse(Matrix3::diagonal({2, 4, 0.5})) == Matrix3::diagonal({0.5, 0.25, 2}));
}

TEST_CASE("a singular matrix inverts to zero, never to NaN", "[math][matrix]") {
    // Rows 0 and 2 are parallel; this is how an immovable body's inverse inertia comes out 0.
    const Matrix3 singular{{1, 2, 3, 0, 1, 1, 2, 4, 6}};
    CHECK(determinant(singular) == 0.0);
    CHECK(inverse(singular) == Matrix3::zero());
    CHECK(inverse(Matrix3::zero()) == Matrix3::zero());
}

TEST_CASE("a quarter turn about z takes x to y", "[math][quaternion]") {
    const Quaternion q = from_axis_angle({0, 0, 1}, std::numbers::pi / 2);
    CHECK_THAT(rotate(q, {1, 0, 0}), is_close_to(Vector3{0, 1, 0}, eps));
    CHECK_THAT(rotate(q, {0, 1, 0}), is_close_to(Vector3{-1, 0, 0}, eps));
    CHECK(rotate(q, {0, 0, 1}) == Vector3{0, 0, 1});
    CHECK(rotate(Quaternion{}, a) == a);
}

TEST_CASE("to_matrix of a unit quaternion is orthonormal with determinant 1", "[math][quaternion]") {
    const Vector3 axis = normalized(Vector3{1, -2, 2});
    for (const double angle : {0.0, 0.3, 1.0, 2.5, std::numbers::pi, 5.0}) {
        CAPTURE(angle);
        const Matrix3 r = to_matrix(from_axis_angle(axis, angle));
        CHECK_THAT(r * transpose(r), is_close_to(Matrix3::identity(), 4 * eps));
        CHECK_THAT(determinant(r), WithinAbs(1.0, 4 * eps));
        // The axis is the one direction the rotation leaves alone.
        CHECK_THAT(r * axis, is_close_to(axis, 4 * eps));
        // The trace of a rotation by theta is 1 + 2 cos(theta).
        CHECK_THAT(r(0, 0) + r(1, 1) + r(2, 2), WithinAbs(1.0 + 2.0 * std::cos(angle), 8 * eps));
    }
}

TEST_CASE("rotating by the matrix matches the quaternion sandwich q v q*", "[math][quaternion]") {
    const Quaternion q = normalized(Quaternion{0.5, -1.0, 2.0, 0.25});
    CHECK_THAT(norm(q), WithinAbs(1.0, 2 * eps));
    for (const Vector3& v : {Vector3{1, 0, 0}, Vector3{0, 1, 0}, Vector3{0, 0, 1}, Vector3{3, -4, 12}}) {
        CAPTURE(v);
        CHECK_THAT(rotate(q, v), is_close_to(rotate_by_sandwich(q, v), 8 * eps * length(v)));
        CHECK_THAT(length(rotate(q, v)), WithinAbs(length(v), 8 * eps * length(v)));
    }
}

TEST_CASE("rotations about one axis compose by adding angles", "[math][quaternion]") {
    const Vector3 axis = normalized(Vector3{2, 3, 6});  // 7 long, so each component is a ratio of 7ths
    const Quaternion sum = from_axis_angle(axis, 0.4) * from_axis_angle(axis, 1.1);
    CHECK_THAT(sum, is_close_to(from_axis_angle(axis, 1.5), 4 * eps));
    CHECK_THAT(from_axis_angle(axis, 0.7) * conjugate(from_axis_angle(axis, 0.7)), is_close_to(Quaternion{}, 2 * eps));
}

TEST_CASE("integrating a constant omega equals one rotation by |omega| t and stays unit", "[math][quaternion]") {
    const Vector3 omega{0.3, -1.2, 0.8};
    const double dt = 1.0 / 240.0;
    const int steps = 2400;
    const Quaternion start = from_axis_angle({0, 0, 1}, 0.25);

    Quaternion q = start;
    double worst_norm_error = 0.0;
    for (int i = 0; i < steps; ++i) {
        q = integrate(q, omega, dt);
        worst_norm_error = std::max(worst_norm_error, std::abs(norm(q) - 1.0));
    }
    const double total_angle = length(omega) * dt * steps;  // about 14.7 rad: more than two turns
    const Quaternion expected = from_axis_angle(omega / length(omega), total_angle) * start;

    CHECK(worst_norm_error <= 2 * eps);
    // One rounding per step: 2400 steps of a few ulps each.
    CHECK_THAT(q, is_close_to(expected, 1e-12));
    // The angle turned, start to end, is |omega| t modulo one full turn of the quaternion (4 pi).
    const double turned = angle_about(q * conjugate(start), omega / length(omega));
    CHECK_THAT(turned, WithinAbs(std::remainder(total_angle, 4 * std::numbers::pi), 1e-12));
}

TEST_CASE("integrating with zero omega or zero dt leaves the orientation exactly as it was", "[math][quaternion]") {
    const Quaternion q = normalized(Quaternion{1, 2, 3, 4});
    CHECK(integrate(q, {}, 0.01) == q);
    CHECK(integrate(q, {1, 2, 3}, 0.0) == q);
}
