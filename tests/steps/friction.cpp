// Public step tests for chapter 6, friction.
// Tags: [friction] chapter, [step:N:name] the step a test grades, [points:P] its weight.
//
// Step 2 lets every right-handed orthonormal frame pass, so the cases of the later steps read
// the friction impulse through the student's own tangent_basis(), and their bodies are balls
// touching on the line of their centres, whose tangential mass is the same along every
// tangent: the answer is then the same in every frame.
#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "feedback.hpp"
#include "friction.hpp"
#include "friction_cases.hpp"
#include "friction_laws.hpp"

using namespace workbook;
namespace laws = workbook::friction_laws;
using workbook::testing::expect_close;
using workbook::testing::expect_finite;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

RigidBody ground() { return make_immovable_plane({0, 0, 1}, {0, 0, 0}); }

/// `body` with dynamic coefficient `mu_d` and static `mu_s`.
RigidBody with_friction(RigidBody body, double mu_d, double mu_s) {
    body.friction = mu_d;
    body.static_friction = mu_s;
    return body;
}

Contact contact_at(const Vector3& normal, const Vector3& point) {
    Contact c;
    c.normal = normal;
    c.add_point(point, 0.0);
    return c;
}

Vector3 point_velocity(const RigidBody& b, const Vector3& p) { return b.velocity + cross(b.angular_velocity, p - b.position); }

/// The friction impulse of a point as a vector, read in the student's own tangents.
Vector3 friction_vector(const PointImpulse& p, const Vector3& normal) {
    const std::array<Vector3, 2> t = friction::tangent_basis(normal);
    return p.friction[0] * t[0] + p.friction[1] * t[1];
}

/// The checks of step 2 on one normal.
void expect_frame(const Vector3& n, const std::string& situation) {
    const std::array<Vector3, 2> t = friction::tangent_basis(n);
    expect_finite(laws::frame, t[0], "", situation + " (t1)");
    expect_finite(laws::frame, t[1], "", situation + " (t2)");
    const double tolerance = rounding_tolerance(1.0, 16);
    expect_close(laws::frame, 1.0, length(t[0]), tolerance, "", situation + " (|t1|)");
    expect_close(laws::frame, 1.0, length(t[1]), tolerance, "", situation + " (|t2|)");
    expect_close(laws::frame, 0.0, dot(t[0], n), tolerance, "", situation + " (t1 . n)");
    expect_close(laws::frame, 0.0, dot(t[1], n), tolerance, "", situation + " (t2 . n)");
    expect_close(laws::frame, 0.0, dot(t[0], t[1]), tolerance, "", situation + " (t1 . t2)");
    expect_close(laws::frame, n, cross(t[0], t[1]), tolerance, "", situation + " (t1 x t2, which must be n)");
}

}  // namespace

TEST_CASE("one material, ice on rubber and two materials: the geometric mean of the coefficients",
          "[friction][step:1:mix-coefficients][points:2]") {
    struct Case {
        double mu1, mu2, mixed;
    };
    for (const Case c : {Case{0.5, 0.5, 0.5}, Case{0.2, 0.8, 0.4}, Case{0.0, 0.9, 0.0}, Case{1.0, 0.25, 0.5}}) {
        expect_close(laws::mix, c.mixed, friction::mix_coefficients(c.mu1, c.mu2), rounding_tolerance(1.0), "",
                     "mu1 = " + format(c.mu1) + ", mu2 = " + format(c.mu2));
    }
}

TEST_CASE("a pair's coefficient lies between its bodies' and does not depend on their order",
          "[friction][step:1:mix-coefficients][points:1]") {
    const double expected = std::sqrt(0.3 * 0.7);  // 0.458..., below the arithmetic mean 0.5
    expect_close(laws::mix, expected, friction::mix_coefficients(0.3, 0.7), rounding_tolerance(1.0), "", "mu1 = 0.3, mu2 = 0.7");
    expect_close(laws::mix, expected, friction::mix_coefficients(0.7, 0.3), rounding_tolerance(1.0), "", "mu1 = 0.7, mu2 = 0.3");
}

TEST_CASE("tangents of the world's six axis normals: finite, unit, at right angles, t1 x t2 = n",
          "[friction][step:2:tangent-basis][points:2]") {
    for (const Vector3 n : {Vector3{0, 0, 1}, Vector3{0, 0, -1}, Vector3{1, 0, 0}, Vector3{-1, 0, 0}, Vector3{0, 1, 0},
                            Vector3{0, -1, 0}})
        expect_frame(n, "normal " + format(n));
}

TEST_CASE("tangents of tilted normals, one a billionth off the z axis, and the same pair every time",
          "[friction][step:2:tangent-basis][points:2]") {
    for (const Vector3 n : {Vector3{0.6, 0, 0.8}, Vector3{0, -0.8, 0.6}, normalized(Vector3{1, 1, 1}), normalized(Vector3{1e-9, 0, 1})})
        expect_frame(n, "normal " + format(n));
    const Vector3 n = normalized(Vector3{-2, 3, 6});
    const std::array<Vector3, 2> first = friction::tangent_basis(n);
    const std::array<Vector3, 2> second = friction::tangent_basis(n);
    expect_close(laws::frame, first[0], second[0], 0.0, "", "normal " + format(n) + ", t1 of two calls");
    expect_close(laws::frame, first[1], second[1], 0.0, "", "normal " + format(n) + ", t2 of two calls");
}

TEST_CASE("a 1 kg ball on the ground: its tangential mass is 2/7 kg along every tangent",
          "[friction][step:3:tangent-mass][points:2]") {
    const RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1});
    for (const Vector3 t : {Vector3{1, 0, 0}, Vector3{0.6, 0.8, 0}})
        expect_close(laws::tangent_mass, 2.0 / 7.0, friction::tangent_mass(ball, ground(), {0, 0, 0}, t),
                     rounding_tolerance(1.0, 32), "kg",
                     "solid ball of 1 kg and radius 0.1 m on the ground, point (0, 0, 0), tangent " + format(t));
}

TEST_CASE("balls of 1 and 3 kg touching: 3/14 kg, both balls' turning included; 0 between two immovable bodies",
          "[friction][step:3:tangent-mass][points:2]") {
    const RigidBody a = make_sphere(1.0, 0.5, {0, 0, 1});
    const RigidBody b = make_sphere(3.0, 0.5, {0, 0, 0});
    // k = (1 + 5/2) (1/m1 + 1/m2): each ball's turning adds 5/2 of its own 1/m.
    expect_close(laws::tangent_mass, 3.0 / 14.0, friction::tangent_mass(a, b, {0, 0, 0.5}, {0, 1, 0}), rounding_tolerance(1.0, 32),
                 "kg", "balls of 1 and 3 kg, radius 0.5 m, at (0, 0, 1) and (0, 0, 0), point (0, 0, 0.5), tangent (0, 1, 0)");
    expect_close(laws::tangent_mass, 0.0,
                 friction::tangent_mass(make_immovable_sphere(1.0, {0, 0, 2}), ground(), {0, 0, 1}, {1, 0, 0}), 0.0, "kg",
                 "an immovable ball on the immovable ground");
}

TEST_CASE("accumulate_friction keeps a sum within mu_s J_n and scales a longer one onto the disc of radius mu_d J_n",
          "[friction][step:4:accumulate-friction][points:3]") {
    struct Case {
        std::array<double, 2> before, increment, after;
        const testing::Law* law;
    };
    const double r = 0.5 / std::sqrt(2.0);
    // J_n = 1, mu_s = 0.6, mu_d = 0.5.
    for (const Case& c : {Case{{0, 0}, {0.3, 0.4}, {0.3, 0.4}, &laws::stick},  // |sum| 0.5 <= 0.6: sticks
                          Case{{0.3, 0}, {0.5, 0.6}, {0.4, 0.3}, &laws::slide},  // (0.8, 0.6), length 1: scaled to 0.5
                          Case{{0, 0}, {0.55, 0}, {0.55, 0}, &laws::stick},  // 0.55: above mu_d but within mu_s
                          Case{{0, 0}, {-0.45, 0.45}, {-r, r}, &laws::slide}}) {  // |sum| 0.636: a square of side 1.2 would keep it
        std::array<double, 2> sum = c.before;
        const std::array<double, 2> expected = c.after;
        const std::array<double, 2> applied = friction::accumulate_friction(sum, c.increment, 1.0, 0.6, 0.5);
        const std::string situation = "accumulated (" + format(c.before[0]) + ", " + format(c.before[1]) + ") kg m/s, increment (" +
                                      format(c.increment[0]) + ", " + format(c.increment[1]) +
                                      "), J_n = 1 kg m/s, mu_s = 0.6, mu_d = 0.5";
        for (std::size_t d = 0; d < 2; ++d) {
            const std::string which = d == 0 ? "first" : "second";
            expect_close(*c.law, expected[d], sum[d], rounding_tolerance(1.0), "kg m/s",
                         situation + " (the new sum's " + which + " component)");
            expect_close(*c.law, expected[d] - c.before[d], applied[d], rounding_tolerance(1.0), "kg m/s",
                         situation + " (the returned change's " + which + " component)");
        }
    }
}

TEST_CASE("no push, no friction: with J_n = 0 the sum becomes 0; a sum left outside a shrunk cone is scaled back",
          "[friction][step:4:accumulate-friction][points:2]") {
    std::array<double, 2> sum{0.2, -0.1};
    std::array<double, 2> applied = friction::accumulate_friction(sum, {0.1, 0.1}, 0.0, 0.6, 0.5);
    const std::string lifted = "accumulated (0.2, -0.1) kg m/s, increment (0.1, 0.1), J_n = 0, mu_s = 0.6, mu_d = 0.5";
    expect_close(laws::no_push, 0.0, sum[0], 0.0, "kg m/s", lifted + " (the new sum's first component)");
    expect_close(laws::no_push, 0.0, sum[1], 0.0, "kg m/s", lifted + " (the new sum's second component)");
    expect_close(laws::no_push, -0.2, applied[0], rounding_tolerance(1.0), "kg m/s", lifted + " (the returned change's first component)");
    expect_close(laws::no_push, 0.1, applied[1], rounding_tolerance(1.0), "kg m/s", lifted + " (the returned change's second component)");
    sum = {0, 0};
    applied = friction::accumulate_friction(sum, {0, 0}, 0.0, 0.0, 0.0);
    expect_finite(laws::no_push, Vector3{sum[0], sum[1], applied[0] + applied[1]}, "kg m/s",
                  "accumulated (0, 0), increment (0, 0), J_n = 0, mu_s = mu_d = 0 (the new sum and the change)");
    sum = {2.0, 0.0};
    applied = friction::accumulate_friction(sum, {0, 0}, 1.0, 0.6, 0.5);
    const std::string shrunk = "accumulated (2, 0) kg m/s from a pass when J_n was larger, increment (0, 0), now J_n = 1, "
                               "mu_s = 0.6, mu_d = 0.5";
    expect_close(laws::slide, 0.5, sum[0], rounding_tolerance(2.0), "kg m/s", shrunk + " (the new sum's first component)");
    expect_close(laws::slide, -1.5, applied[0], rounding_tolerance(2.0), "kg m/s", shrunk + " (the returned change's first component)");
}

TEST_CASE("a 1 kg ball sliding at 0.7 m/s on the ground with friction to spare ends rolling at 0.5 m/s",
          "[friction][step:5:solve-friction][points:3]") {
    RigidBody ball = with_friction(make_sphere(1.0, 0.1, {0, 0, 0.1}, {0.7, 0, 0}), 0.5, 0.5);
    RigidBody floor = with_friction(ground(), 0.5, 0.5);
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].normal = 10.0;
    impulses.points[0].mass = 1.0;
    const double change = friction::solve_friction(ball, floor, contact, impulses);
    const std::string situation = "solid ball, 1 kg, r = 0.1 m, sliding at 0.7 m/s, accumulated normal impulse 10 kg m/s, mu = 0.5";
    expect_close(laws::slip_stops, Vector3{0.5, 0, 0}, ball.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (its velocity)");
    expect_close(laws::slip_stops, Vector3{0, 5, 0}, ball.angular_velocity, rounding_tolerance(5.0, 64), "rad/s",
                 situation + " (its spin, 2/7 kg m/s of friction turning it)");
    expect_close(laws::slip_stops, Vector3{}, point_velocity(ball, {0, 0, 0}), rounding_tolerance(1.0, 64), "m/s",
                 situation + " (the slip at the contact point after the pass)");
    expect_close(laws::pass_cone, Vector3{-0.2, 0, 0}, friction_vector(impulses.points[0], contact.normal), rounding_tolerance(1.0, 64),
                 "kg m/s", situation + " (the accumulated friction, friction[0] t1 + friction[1] t2 in your tangents)");
    expect_close(laws::pass_change, 0.7, change, rounding_tolerance(1.0, 64), "m/s", situation + " (the returned change of slip)");
}

TEST_CASE("with 0.2 kg m/s of normal impulse, mu_s = 0.6 and mu_d = 0.5 the ball slides on, slowed by 0.1 m/s",
          "[friction][step:5:solve-friction][points:3]") {
    RigidBody ball = with_friction(make_sphere(1.0, 0.1, {0, 0, 0.1}, {0.7, 0, 0}), 0.5, 0.6);
    RigidBody floor = with_friction(ground(), 0.5, 0.6);
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].normal = 0.2;
    impulses.points[0].mass = 1.0;
    const double change = friction::solve_friction(ball, floor, contact, impulses);
    // Stopping the slip needs 2/7 x 0.7 = 0.2 kg m/s, more than mu_s J_n = 0.12: it slides with mu_d J_n = 0.1.
    const double mu_s = friction_cases::pair_coefficient(0.6, 0.6);
    const double mu_d = friction_cases::pair_coefficient(0.5, 0.5);
    const double f = friction_cases::coulomb(0.2, 0.2, mu_s, mu_d);
    const std::string situation = "ball of 1 kg, r = 0.1 m, sliding at 0.7 m/s, accumulated normal impulse 0.2 kg m/s, the pair's mu_s = " +
                                  format(mu_s) + " and mu_d = " + format(mu_d) + " (as your mix_coefficients() gives them)";
    expect_close(laws::pass_cone, Vector3{-f, 0, 0}, friction_vector(impulses.points[0], contact.normal), rounding_tolerance(1.0, 64),
                 "kg m/s", situation + " (the accumulated friction, in your tangents)");
    expect_close(laws::pass_apply, Vector3{0.7 - f, 0, 0}, ball.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (its velocity)");
    expect_close(laws::pass_apply, Vector3{0, 25.0 * f, 0}, ball.angular_velocity, rounding_tolerance(5.0, 64), "rad/s",
                 situation + " (its spin: I^-1 (r x J), I = 0.004 kg m^2)");
    expect_close(laws::pass_change, 3.5 * f, change, rounding_tolerance(1.0, 64), "m/s",
                 situation + " (the returned change of slip: 0.7 m/s before)");
}

TEST_CASE("two balls of 1 and 3 kg sliding past each other at 2 m/s stop slipping, momentum kept",
          "[friction][step:5:solve-friction][points:2]") {
    RigidBody a = with_friction(make_sphere(1.0, 0.5, {1, 0, 0}, {0, 1, 0}), 1.0, 1.0);
    RigidBody b = with_friction(make_sphere(3.0, 0.5, {0, 0, 0}, {0, -1, 0}), 1.0, 1.0);
    const Contact contact = contact_at({1, 0, 0}, {0.5, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].normal = 10.0;
    (void)friction::solve_friction(a, b, contact, impulses);
    const std::string situation = "balls of 1 and 3 kg, radius 0.5 m, touching at (0.5, 0, 0), moving at (0, 1, 0) and (0, -1, 0) m/s, "
                                  "normal impulse 10 kg m/s, mu = 1";
    // J = -2 m/s / k with k = 3.5 (1 + 1/3) 1/kg: 3/7 kg m/s along -y on ball 1.
    expect_close(laws::slip_stops, Vector3{0, 4.0 / 7.0, 0}, a.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (ball 1's velocity)");
    expect_close(laws::pass_apply, Vector3{0, -6.0 / 7.0, 0}, b.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (ball 2's velocity)");
    expect_close(laws::pass_apply, Vector3{0, -2, 0}, 1.0 * a.velocity + 3.0 * b.velocity, rounding_tolerance(4.0, 64), "kg m/s",
                 situation + " (the momentum of the two)");
    expect_close(laws::slip_stops, Vector3{}, point_velocity(a, {0.5, 0, 0}) - point_velocity(b, {0.5, 0, 0}), rounding_tolerance(2.0, 64),
                 "m/s", situation + " (the slip after the pass)");
}

TEST_CASE("a ball leaving the ground takes back the friction warm starting gave it: no push, no friction",
          "[friction][step:5:solve-friction][points:2]") {
    RigidBody ball = with_friction(make_sphere(1.0, 0.1, {0, 0, 0.1}, {0.7, 0, 0.5}), 0.5, 0.5);
    RigidBody floor = with_friction(ground(), 0.5, 0.5);
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].normal = 0.0;  // the normal pass found the ball leaving
    impulses.points[0].friction = {0.3, -0.1};  // warm started from the last step
    const Vector3 given = friction_vector(impulses.points[0], contact.normal);
    (void)friction::solve_friction(ball, floor, contact, impulses);
    const std::string situation = "ball of 1 kg, r = 0.1 m, leaving the ground at (0.7, 0, 0.5) m/s, accumulated normal impulse 0, "
                                  "friction (0.3, -0.1) kg m/s warm started";
    expect_close(laws::pass_cone, 0.0, impulses.points[0].friction[0], 0.0, "kg m/s", situation + " (friction[0] after the pass)");
    expect_close(laws::pass_cone, 0.0, impulses.points[0].friction[1], 0.0, "kg m/s", situation + " (friction[1] after the pass)");
    expect_close(laws::pass_apply, Vector3{0.7, 0, 0.5} - given, ball.velocity, rounding_tolerance(1.0, 64), "m/s",
                 situation + " (its velocity: the friction taken back, " + format(-given) + " kg m/s)");
}

TEST_CASE("a ball on a 30 degree slope: rolls at 5/7 g sin theta with mu_s = 0.2, slides at g (sin - mu_d cos) with mu_s = 0.15",
          "[friction][step:5:solve-friction][points:3]") {
    const double theta = std::numbers::pi / 6;  // 2/7 tan theta = 0.165
    const double g = 9.81;
    const double dt = 1.0 / 60;
    const int steps = 60;
    const double t = steps * dt;
    for (const double static_friction : {0.2, 0.15}) {  // mu_d = 0.1 could not hold it
        friction_cases::BallOnSlope ball = friction_cases::ball_on_slope(2.0, 0.25, 0.1, static_friction);
        friction_cases::roll_down(ball, theta, dt, steps, g);
        const double mu_s = friction_cases::pair_coefficient(static_friction, static_friction);
        const double mu_d = friction_cases::pair_coefficient(0.1, 0.1);
        const friction_cases::SlopeMotion expected = friction_cases::slope_motion(theta, g, t, 0.25, mu_s, mu_d);
        const std::string situation = "ball of 2 kg, r = 0.25 m, on a slope of 30 degrees, the pair's mu_s = " + format(mu_s) +
                                      " and mu_d = " + format(mu_d) + " (as your mix_coefficients() gives them), after 60 steps of 1/60 s: " +
                                      (expected.rolls ? "it rolls" : "it slides");
        expect_close(laws::slope, expected.speed, ball.ball.velocity.x, rounding_tolerance(5.0, 4096), "m/s", situation + " (its speed down the slope)");
        expect_close(laws::slope, expected.spin, ball.ball.angular_velocity.y, rounding_tolerance(20.0, 4096), "rad/s", situation + " (its spin)");
    }
}
