// Placeholder public step tests for chapter 6, friction (the chapter's graded side replaces
// this file): one case a step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>

#include "feedback.hpp"
#include "friction.hpp"
#include "friction_laws.hpp"

using namespace workbook;
namespace laws = workbook::friction_laws;
using workbook::testing::expect_close;
using workbook::testing::rounding_tolerance;

TEST_CASE("steel 0.8 on rubber 0.2 gives 0.4", "[friction][step:1:mix-coefficients][points:2]") {
    expect_close(laws::mixed, 0.4, friction::mix_coefficients(0.8, 0.2), rounding_tolerance(0.4), "", "mu1 0.8, mu2 0.2");
}

TEST_CASE("the tangents of the normal +z", "[friction][step:2:tangent-basis][points:2]") {
    const auto [t1, t2] = friction::tangent_basis({0, 0, 1});
    expect_close(laws::frame, Vector3{0, 0, 1}, cross(t1, t2), rounding_tolerance(1.0), "", "normal (0, 0, 1)");
}

TEST_CASE("a 1 kg ball on the ground: 2/7 kg along a tangent", "[friction][step:3:tangent-mass][points:2]") {
    const RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1});
    const RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    expect_close(laws::tangent_mass, 2.0 / 7.0, friction::tangent_mass(ball, ground, {0, 0, 0}, {1, 0, 0}),
                 rounding_tolerance(1.0), "kg", "ball of radius 0.1 m, point below its centre, tangent +x");
}

TEST_CASE("beyond the static cone the pair slides at mu_d J_n", "[friction][step:4:accumulate-friction][points:2]") {
    std::array<double, 2> sum{0.0, 0.0};
    const auto applied = friction::accumulate_friction(sum, {3.0, 4.0}, 1.0, 0.6, 0.5);
    expect_close(laws::cone, 0.3, sum[0], rounding_tolerance(1.0), "kg m/s", "increment (3, 4), J_n 1, mu_s 0.6, mu_d 0.5");
    expect_close(laws::cone, 0.4, applied[1], rounding_tolerance(1.0), "kg m/s", "increment (3, 4), J_n 1, mu_s 0.6, mu_d 0.5");
}

TEST_CASE("a ball sliding at 0.7 m/s ends rolling at 0.5 m/s", "[friction][step:5:solve-friction][points:2]") {
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
    impulses.points[0].normal = 10.0;
    (void)friction::solve_friction(ball, ground, contact, impulses);
    expect_close(laws::pass, 0.5, ball.velocity.x, rounding_tolerance(1.0, 64), "m/s", "1 kg ball, J_n 10 kg m/s, mu 0.5");
}
