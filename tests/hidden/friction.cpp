// Hidden step tests for chapter 6, friction: the same steps and laws as the public tests, on
// other numbers and the cases a shortcut misses (normals along the negative axes, a box whose
// tangential masses differ along its two tangents, a moving platform, ice, a sum pointing
// backwards, several points at once).
#include <catch2/catch_test_macros.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "../steps/friction_cases.hpp"
#include "../steps/friction_laws.hpp"
#include "feedback.hpp"
#include "friction.hpp"

using namespace workbook;
namespace laws = workbook::friction_laws;
using workbook::testing::expect_at_least;
using workbook::testing::expect_close;
using workbook::testing::expect_finite;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

RigidBody with_friction(RigidBody body, double mu_d, double mu_s) {
    body.friction = mu_d;
    body.static_friction = mu_s;
    return body;
}

Vector3 point_velocity(const RigidBody& b, const Vector3& p) { return b.velocity + cross(b.angular_velocity, p - b.position); }

Vector3 friction_vector(const PointImpulse& p, const Vector3& normal) {
    const std::array<Vector3, 2> t = friction::tangent_basis(normal);
    return p.friction[0] * t[0] + p.friction[1] * t[1];
}

}  // namespace

TEST_CASE("hidden: mixing coefficients from a millionth to ten", "[friction][step:1:mix-coefficients][points:2]") {
    struct Case {
        double mu1, mu2, mixed;
    };
    for (const Case c : {Case{0.04, 0.81, 0.18}, Case{1e-6, 1e-6, 1e-6}, Case{10.0, 0.1, 1.0}, Case{0.0, 0.0, 0.0}, Case{0.64, 0.0, 0.0},
                         Case{2.25, 1.0, 1.5}})
        expect_close(laws::mix, c.mixed, friction::mix_coefficients(c.mu1, c.mu2), rounding_tolerance(c.mixed), "",
                     "mu1 = " + format(c.mu1) + ", mu2 = " + format(c.mu2));
}

TEST_CASE("hidden: tangents of normals along and next to the negative axes", "[friction][step:2:tangent-basis][points:2]") {
    for (const Vector3 n : {Vector3{0, 0, -1}, Vector3{-1, 0, 0}, Vector3{0, -1, 0}, normalized(Vector3{-1, 1e-7, 0}),
                            normalized(Vector3{1e-12, -1, 1e-12}), Vector3{0.48, -0.6, 0.64}, Vector3{-0.8, 0, -0.6}}) {
        const std::array<Vector3, 2> t = friction::tangent_basis(n);
        const std::string situation = "normal " + format(n);
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
}

TEST_CASE("hidden: a 2 kg box's corner has different tangential masses along x and y",
          "[friction][step:3:tangent-mass][points:2]") {
    // Half extents (0.2, 0.1, 0.1): I = m/3 (0.02, 0.05, 0.05) kg m^2, corner r = (0.2, 0.1, -0.1).
    const RigidBody box = make_box(2.0, {0.2, 0.1, 0.1}, {0, 0, 0.1});
    const RigidBody floor = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    const std::string situation = "a 2 kg box of half extents (0.2, 0.1, 0.1) m on the ground, point at its corner (0.2, 0.1, 0)";
    expect_close(laws::tangent_mass, 1.0 / 1.1, friction::tangent_mass(box, floor, {0.2, 0.1, 0}, {1, 0, 0}), rounding_tolerance(1.0, 64),
                 "kg", situation + ", tangent (1, 0, 0): k = 0.5 + 0.6");
    expect_close(laws::tangent_mass, 1.0 / 2.45, friction::tangent_mass(box, floor, {0.2, 0.1, 0}, {0, 1, 0}), rounding_tolerance(1.0, 64),
                 "kg", situation + ", tangent (0, 1, 0): k = 0.5 + 1.95");
}

TEST_CASE("hidden: a ball on a moving platform, the platform as body 1", "[friction][step:3:tangent-mass][points:2]") {
    RigidBody platform = make_immovable_plane({0, 0, -1}, {0, 0, 0});
    platform.velocity = {1, 0, 0};
    const RigidBody ball = make_sphere(3.5, 0.2, {0, 0, -0.2});
    expect_close(laws::tangent_mass, 1.0, friction::tangent_mass(platform, ball, {0, 0, 0}, {0, 1, 0}), rounding_tolerance(1.0, 32), "kg",
                 "a 3.5 kg ball of radius 0.2 m under a moving immovable platform (body 1), tangent (0, 1, 0): 2/7 of 3.5 kg");
}

TEST_CASE("hidden: accumulate_friction with J_n = 2, mu_s = 0.5, mu_d = 0.3, on ice, and backwards",
          "[friction][step:4:accumulate-friction][points:3]") {
    struct Case {
        std::array<double, 2> before, increment;
        double mu_s, mu_d;
        std::array<double, 2> after;
        const testing::Law* law;
    };
    const double q = 0.6 / std::sqrt(2.0);
    for (const Case& c : {Case{{0.6, -0.2}, {0.2, 0.5}, 0.5, 0.3, {0.8, 0.3}, &laws::stick},          // 0.854 <= 1: sticks
                          Case{{0.9, 0}, {0.3, 0.5}, 0.5, 0.3, {1.2 * 0.6 / 1.3, 0.5 * 0.6 / 1.3}, &laws::slide},  // (1.2, 0.5): 1.3 > 1
                          Case{{0, 0}, {-1.2, -1.6}, 0.5, 0.3, {-0.36, -0.48}, &laws::slide},      // length 2, backwards
                          Case{{0.5, 0.5}, {0.4, 0.4}, 0.5, 0.3, {q, q}, &laws::slide},            // (0.9, 0.9): in a square of 1
                          Case{{0.2, 0.1}, {0.1, 0.0}, 0.0, 0.0, {0.0, 0.0}, &laws::slide}}) {      // ice
        std::array<double, 2> sum = c.before;
        const std::array<double, 2> applied = friction::accumulate_friction(sum, c.increment, 2.0, c.mu_s, c.mu_d);
        const std::string situation = "accumulated (" + format(c.before[0]) + ", " + format(c.before[1]) + ") kg m/s, increment (" +
                                      format(c.increment[0]) + ", " + format(c.increment[1]) + "), J_n = 2 kg m/s, mu_s = " +
                                      format(c.mu_s) + ", mu_d = " + format(c.mu_d);
        for (std::size_t d = 0; d < 2; ++d) {
            const std::string which = d == 0 ? "first" : "second";
            expect_close(*c.law, c.after[d], sum[d], rounding_tolerance(2.0), "kg m/s", situation + " (the new sum's " + which + " component)");
            expect_close(*c.law, c.after[d] - c.before[d], applied[d], rounding_tolerance(2.0), "kg m/s",
                         situation + " (the returned change's " + which + " component)");
        }
    }
}

TEST_CASE("hidden: a sum exactly on the rim of the static cone sticks; with J_n = 0 and nothing accumulated nothing happens",
          "[friction][step:4:accumulate-friction][points:2]") {
    std::array<double, 2> sum{0.0, 0.0};
    std::array<double, 2> applied = friction::accumulate_friction(sum, {0.75, 1.0}, 2.5, 0.5, 0.25);  // |sum| = 1.25 = mu_s J_n
    const std::string rim = "accumulated (0, 0), increment (0.75, 1) kg m/s, J_n = 2.5 kg m/s, mu_s = 0.5, mu_d = 0.25: |sum| = mu_s J_n";
    expect_close(laws::stick, 0.75, sum[0], rounding_tolerance(1.0), "kg m/s", rim + " (the new sum's first component)");
    expect_close(laws::stick, 1.0, sum[1], rounding_tolerance(1.0), "kg m/s", rim + " (the new sum's second component)");
    sum = {0.0, 0.0};
    applied = friction::accumulate_friction(sum, {0.0, 0.0}, 0.0, 0.5, 0.25);
    const Vector3 all{sum[0], sum[1], applied[0] + applied[1]};
    expect_finite(laws::no_push, all, "kg m/s", "accumulated (0, 0), increment (0, 0), J_n = 0 (the new sum and the change)");
    expect_close(laws::no_push, Vector3{}, all, 0.0, "kg m/s", "accumulated (0, 0), increment (0, 0), J_n = 0 (the new sum and the change)");
}

TEST_CASE("hidden: a ball at rest on a conveyor belt moving at 1 m/s is carried along, rolling, the belt unmoved",
          "[friction][step:5:solve-friction][points:3]") {
    RigidBody ball = with_friction(make_sphere(2.0, 0.3, {0, 0, 0.3}), 0.6, 0.8);
    RigidBody belt = with_friction(make_immovable_plane({0, 0, 1}, {0, 0, 0}), 0.6, 0.8);
    belt.velocity = {1, 0, 0};
    Contact contact;
    contact.normal = {0, 0, 1};
    contact.add_point({0, 0, 0}, 0.0);
    ContactImpulses impulses;
    impulses.points[0].normal = 5.0;
    impulses.points[0].mass = 2.0;
    const double change = friction::solve_friction(ball, belt, contact, impulses);
    const std::string situation = "ball of 2 kg, r = 0.3 m, at rest on a belt (immovable, moving at (1, 0, 0) m/s), normal impulse 5 kg m/s";
    expect_close(laws::slip_stops, Vector3{2.0 / 7.0, 0, 0}, ball.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (its velocity)");
    expect_close(laws::slip_stops, Vector3{1, 0, 0}, point_velocity(ball, {0, 0, 0}), rounding_tolerance(1.0, 64), "m/s",
                 situation + " (its contact point's velocity, the belt's)");
    expect_close(laws::pass_apply, Vector3{1, 0, 0}, belt.velocity, 0.0, "m/s", situation + " (the belt's velocity)");
    expect_close(laws::pass_apply, Vector3{}, belt.angular_velocity, 0.0, "rad/s", situation + " (the belt's spin)");
    expect_close(laws::pass_change, 1.0, change, rounding_tolerance(1.0, 64), "m/s", situation + " (the returned change of slip)");
}

TEST_CASE("hidden: on ice the friction warm starting gave is taken back", "[friction][step:5:solve-friction][points:2]") {
    RigidBody ball = with_friction(make_sphere(1.0, 0.1, {0, 0, 0.1}, {0.4, 0.3, 0}), 0.0, 0.0);
    RigidBody floor = with_friction(make_immovable_plane({0, 0, 1}, {0, 0, 0}), 0.0, 0.0);
    Contact contact;
    contact.normal = {0, 0, 1};
    contact.add_point({0, 0, 0}, 0.0);
    ContactImpulses impulses;
    impulses.points[0].normal = 1.0;
    impulses.points[0].friction = {0.2, 0.1};
    const Vector3 given = friction_vector(impulses.points[0], contact.normal);
    (void)friction::solve_friction(ball, floor, contact, impulses);
    const std::string situation = "an ice ball (mu = 0) of 1 kg on ice sliding at (0.4, 0.3, 0) m/s, normal impulse 1 kg m/s, "
                                  "friction (0.2, 0.1) kg m/s warm started";
    expect_close(laws::pass_cone, 0.0, impulses.points[0].friction[0], 0.0, "kg m/s", situation + " (friction[0] after the pass)");
    expect_close(laws::pass_cone, 0.0, impulses.points[0].friction[1], 0.0, "kg m/s", situation + " (friction[1] after the pass)");
    expect_close(laws::pass_apply, Vector3{0.4, 0.3, 0} - given, ball.velocity, rounding_tolerance(1.0, 64), "m/s", situation + " (its velocity)");
}

TEST_CASE("hidden: a box sliding on four corners with little normal impulse: mu_d J_n at each, the box's momentum changed by their sum",
          "[friction][step:5:solve-friction][points:3]") {
    RigidBody box = with_friction(make_box(2.0, {0.2, 0.1, 0.1}, {0, 0, 0.1}, {}, {1.0, 0.5, 0}), 0.4, 0.5);
    RigidBody floor = with_friction(make_immovable_plane({0, 0, 1}, {0, 0, 0}), 0.4, 0.5);
    Contact contact;
    contact.normal = {0, 0, 1};
    for (const Vector3 p : {Vector3{0.2, 0.1, 0}, Vector3{0.2, -0.1, 0}, Vector3{-0.2, -0.1, 0}, Vector3{-0.2, 0.1, 0}}) contact.add_point(p, 0.0);
    ContactImpulses impulses;
    const std::array<double, 4> normal{0.1, 0.2, 0.05, 0.15};
    for (std::size_t i = 0; i < 4; ++i) impulses.points[i].normal = normal[i];
    const Vector3 before = box.velocity;
    const double mu_d = friction_cases::pair_coefficient(0.4, 0.4);
    (void)friction::solve_friction(box, floor, contact, impulses);
    const std::string situation = "a 2 kg box of half extents (0.2, 0.1, 0.1) m sliding at (1, 0.5, 0) m/s on its four bottom corners, "
                                  "normal impulses 0.1, 0.2, 0.05, 0.15 kg m/s, mu_s = 0.5, mu_d = 0.4 (the pair's mu_d as your mix_coefficients() gives it: " +
                                  format(mu_d) + ")";
    Vector3 total{};
    for (std::size_t i = 0; i < 4; ++i) {
        const Vector3 f = friction_vector(impulses.points[i], contact.normal);
        total += f;
        expect_close(laws::pass_cone, mu_d * normal[i], length(f), rounding_tolerance(1.0, 64), "kg m/s",
                     situation + " (the length of corner " + std::to_string(i + 1) + "'s friction: it slides)");
        expect_at_least(laws::pass_cone, 0.0, -dot(f, Vector3{1.0, 0.5, 0}), rounding_tolerance(1.0, 64), "kg m/s",
                        situation + " (corner " + std::to_string(i + 1) + "'s friction against the slide, - F . v)");
    }
    expect_close(laws::pass_apply, total, 2.0 * (box.velocity - before), rounding_tolerance(1.0, 64), "kg m/s",
                 situation + " (the box's change of momentum, the sum of the four frictions)");
}

TEST_CASE("hidden: a ball on a 40 degree slope: rolls with mu_s = 0.3, slides with mu_s = 0.2",
          "[friction][step:5:solve-friction][points:3]") {
    const double theta = 40.0 * std::numbers::pi / 180.0;  // 2/7 tan theta = 0.2397
    const double g = 9.81;
    const double dt = 1.0 / 120;
    const int steps = 90;
    const double t = steps * dt;
    for (const double static_friction : {0.3, 0.2}) {
        friction_cases::BallOnSlope ball = friction_cases::ball_on_slope(0.5, 0.05, 0.15, static_friction);
        friction_cases::roll_down(ball, theta, dt, steps, g);
        const double mu_s = friction_cases::pair_coefficient(static_friction, static_friction);
        const double mu_d = friction_cases::pair_coefficient(0.15, 0.15);
        const friction_cases::SlopeMotion expected = friction_cases::slope_motion(theta, g, t, 0.05, mu_s, mu_d);
        const std::string situation = "ball of 0.5 kg, r = 0.05 m, on a slope of 40 degrees, the pair's mu_s = " + format(mu_s) +
                                      " and mu_d = " + format(mu_d) + ", after 90 steps of 1/120 s: " + (expected.rolls ? "it rolls" : "it slides");
        expect_close(laws::slope, expected.speed, ball.ball.velocity.x, rounding_tolerance(10.0, 4096), "m/s", situation + " (its speed down the slope)");
        expect_close(laws::slope, expected.spin, ball.ball.angular_velocity.y, rounding_tolerance(200.0, 4096), "rad/s", situation + " (its spin)");
    }
}
