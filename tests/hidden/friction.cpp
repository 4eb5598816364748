// Placeholder hidden step tests for chapter 6, friction (the chapter's graded side replaces
// this file): one case a step, on other numbers than the public ones.
#include <catch2/catch_test_macros.hpp>

#include <cmath>

#include "../steps/friction_laws.hpp"
#include "feedback.hpp"
#include "friction.hpp"

using namespace workbook;
namespace laws = workbook::friction_laws;
using workbook::testing::expect_close;
using workbook::testing::rounding_tolerance;

TEST_CASE("hidden: 0.9 and 0.1 give 0.3", "[friction][step:1:mix-coefficients][points:2]") {
    expect_close(laws::mixed, 0.3, friction::mix_coefficients(0.9, 0.1), rounding_tolerance(0.3), "", "mu1 0.9, mu2 0.1");
}

TEST_CASE("hidden: the tangents of the normal -x", "[friction][step:2:tangent-basis][points:2]") {
    const auto [t1, t2] = friction::tangent_basis({-1, 0, 0});
    expect_close(laws::frame, Vector3{-1, 0, 0}, cross(t1, t2), rounding_tolerance(1.0), "", "normal (-1, 0, 0)");
}

TEST_CASE("hidden: a 2 kg ball on the ground: 4/7 kg along a tangent", "[friction][step:3:tangent-mass][points:2]") {
    const RigidBody ball = make_sphere(2.0, 0.3, {0, 0, 0.3});
    const RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    expect_close(laws::tangent_mass, 4.0 / 7.0, friction::tangent_mass(ball, ground, {0, 0, 0}, {0, 1, 0}),
                 rounding_tolerance(1.0), "kg", "ball of radius 0.3 m, point below its centre, tangent +y");
}

TEST_CASE("hidden: within the static cone the pair is kept", "[friction][step:4:accumulate-friction][points:2]") {
    std::array<double, 2> sum{0.1, 0.0};
    (void)friction::accumulate_friction(sum, {0.2, 0.4}, 1.0, 0.6, 0.5);
    expect_close(laws::cone, 0.4, sum[1], rounding_tolerance(1.0), "kg m/s", "accumulated (0.1, 0), increment (0.2, 0.4), J_n 1, mu_s 0.6");
}

TEST_CASE("hidden: no normal impulse, no friction", "[friction][step:5:solve-friction][points:2]") {
    RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1}, {0.7, 0, 0});
    ball.friction = ball.static_friction = 0.5;
    RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    ground.friction = ground.static_friction = 0.5;
    Contact contact;
    contact.body1 = 0;
    contact.body2 = 1;
    contact.normal = {0, 0, 1};
    contact.add_point({0, 0, 0}, 0.0);
    ContactImpulses impulses;
    impulses.points[0].friction = {-0.2, 0.0};  // from an earlier pass, when the point still pushed
    (void)friction::solve_friction(ball, ground, contact, impulses);
    expect_close(laws::pass, 0.0, impulses.points[0].friction[0], 0.0, "kg m/s", "J_n 0, friction -0.2 kg m/s before");
}
