// Public step tests for chapter 1, perfectly inelastic collision.
// Tags: [inelastic] chapter, [step:N:name] the step a test grades, [points:P] its weight.
#include <catch2/catch_test_macros.hpp>

#include "feedback.hpp"
#include "sent_values.hpp"
#include "inelastic.hpp"
#include "inelastic_laws.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::inelastic_laws;
using workbook::testing::describe;
using workbook::testing::expect_close;
using workbook::testing::rounding_tolerance;

namespace {

RigidBody ball(double mass, Vector3 position, Vector3 velocity) { return make_sphere(mass, 0.5, position, velocity); }

/// A contact whose normal points from body 2 to body 1, as detection reports it.
Contact contact_between(const RigidBody& body1, const RigidBody& body2) {
    Contact c;
    c.normal = normalized(body1.position - body2.position);
    c.add_point((body1.position + body2.position) / 2.0, 0.01);
    return c;
}

std::string pair_text(const RigidBody& a, const RigidBody& b) { return "body 1: " + describe(a) + "; body 2: " + describe(b); }

Vector3 momentum(const RigidBody& a, const RigidBody& b) { return a.mass() * a.velocity + b.mass() * b.velocity; }

/// The size of the momenta that go into a sum, which sets how exact the sum can be.
double momentum_scale(const RigidBody& a, const RigidBody& b) {
    return a.mass() * length(a.velocity) + b.mass() * length(b.velocity);
}

}  // namespace

TEST_CASE("common velocity of a 2 kg cart at 3 m/s and a 1 kg cart at rest", "[inelastic][step:1:common-velocity][points:2]") {
    const RigidBody cart1 = ball(2.0, {0, 0, 0}, {3, 0, 0});
    const RigidBody cart2 = ball(1.0, {0.9, 0, 0}, {0, 0, 0});
    expect_close(laws::momentum, Vector3{2, 0, 0}, inelastic::common_velocity(cart1, cart2), rounding_tolerance(3.0), "m/s",
                 pair_text(cart1, cart2));
}

TEST_CASE("the common velocity carries the total momentum, in 3D", "[inelastic][step:1:common-velocity][points:2]") {
    const RigidBody body1 = ball(0.25, {0, 0, 0}, {4, -1, 2});
    const RigidBody body2 = ball(3.0, {0.5, 0.5, 0}, {-1, 2, 0.5});
    const Vector3 shared = inelastic::common_velocity(body1, body2);
    const Vector3 before = momentum(body1, body2);
    expect_close(laws::momentum, before, (body1.mass() + body2.mass()) * shared, rounding_tolerance(momentum_scale(body1, body2)),
                 "kg m/s", pair_text(body1, body2));
}

TEST_CASE("head-on carts leave together", "[inelastic][step:2:stick-together][points:2]") {
    RigidBody cart1 = ball(2.0, {-0.45, 0, 0}, {3, 0, 0});
    RigidBody cart2 = ball(1.0, {0.45, 0, 0}, {-3, 0, 0});
    const std::string situation = pair_text(cart1, cart2);
    const double scale = momentum_scale(cart1, cart2);
    const Contact contact = contact_between(cart1, cart2);
    const RigidBody cart1_before = cart1;
    const RigidBody cart2_before = cart2;
    inelastic::resolve(cart1, cart2, contact);
    const bool unchanged = laws::untouched(cart1_before, cart2_before, cart1, cart2);
    expect_close(laws::stick_after(unchanged), Vector3{}, cart1.velocity - cart2.velocity, rounding_tolerance(3.0), "m/s",
                 situation + " (relative velocity v1' - v2' after)");
    expect_close(laws::momentum, Vector3{3, 0, 0}, momentum(testing::judged(cart1_before, cart1), testing::judged(cart2_before, cart2)),
                 rounding_tolerance(scale), "kg m/s", situation);
}

TEST_CASE("an oblique crash merges the whole velocity, not only its normal part", "[inelastic][step:2:stick-together][points:2]") {
    RigidBody car1 = ball(1500.0, {0, 0, 0}, {20, 0, 0});
    RigidBody car2 = ball(1000.0, {0.6, 0.8, 0}, {0, -15, 0});
    const std::string situation = pair_text(car1, car2);
    const Contact contact = contact_between(car1, car2);
    const RigidBody car1_before = car1;
    const RigidBody car2_before = car2;
    inelastic::resolve(car1, car2, contact);
    const bool unchanged = laws::untouched(car1_before, car2_before, car1, car2);
    expect_close(laws::stick_after(unchanged), Vector3{}, car1.velocity - car2.velocity, rounding_tolerance(20.0), "m/s",
                 situation + " (relative velocity v1' - v2' after)");
}

TEST_CASE("a ball hitting an immovable wall stops against it", "[inelastic][step:3:immovable-bodies][points:2]") {
    RigidBody ball1 = ball(2.0, {0, 0, 0}, {-3, 1, 0});
    RigidBody wall = make_immovable_sphere(1.0, {-1.4, 0, 0});
    const std::string situation = pair_text(ball1, wall);
    const Contact contact = contact_between(ball1, wall);
    const RigidBody ball1_before = ball1;
    const RigidBody wall_before = wall;
    inelastic::resolve(ball1, wall, contact);
    const bool unchanged = laws::untouched(ball1_before, wall_before, ball1, wall);
    expect_close(laws::immovable, Vector3{}, wall.velocity, 0.0, "m/s", situation + " (the wall's velocity after)");
    expect_close(laws::immovable_after(unchanged), Vector3{}, ball1.velocity, 0.0, "m/s", situation + " (the ball's velocity after)");
}

TEST_CASE("an immovable body on either side, and two immovable bodies", "[inelastic][step:3:immovable-bodies][points:2]") {
    // A moving platform, so that stopping the ball instead of giving it the platform's velocity fails.
    const Vector3 platform_velocity{1.5, 0, 0};
    RigidBody platform = make_immovable_sphere(1.0, {0, 0, 0});
    platform.velocity = platform_velocity;
    RigidBody ball2 = ball(5.0, {0, 1.4, 0}, {0, -2, 0});
    std::string situation = pair_text(platform, ball2);
    const RigidBody ball2_before = ball2;
    inelastic::resolve(platform, ball2, contact_between(platform, ball2));
    bool unchanged = platform.velocity == platform_velocity && ball2.velocity == ball2_before.velocity;
    expect_close(laws::immovable, platform_velocity, platform.velocity, 0.0, "m/s", situation + " (the platform, body 1, after)");
    expect_close(laws::immovable_after(unchanged), platform_velocity, ball2.velocity, rounding_tolerance(2.0), "m/s",
                 situation + " (the ball, body 2, after)");

    RigidBody ball1 = ball(5.0, {0, 1.4, 0}, {0, -2, 0});
    situation = pair_text(ball1, platform);
    const RigidBody ball1_before = ball1;
    inelastic::resolve(ball1, platform, contact_between(ball1, platform));
    unchanged = platform.velocity == platform_velocity && ball1.velocity == ball1_before.velocity;
    expect_close(laws::immovable, platform_velocity, platform.velocity, 0.0, "m/s", situation + " (the platform, body 2, after)");
    expect_close(laws::immovable_after(unchanged), platform_velocity, ball1.velocity, rounding_tolerance(2.0), "m/s",
                 situation + " (the ball, body 1, after)");

    RigidBody wall1 = make_immovable_sphere(1.0, {0, 0, 0});
    RigidBody wall2 = make_immovable_sphere(1.0, {1.5, 0, 0});
    const Vector3 shared = inelastic::common_velocity(wall1, wall2);
    workbook::testing::expect_finite(laws::immovable, shared, "m/s", "two immovable bodies: common_velocity");
}

TEST_CASE("a pair already moving apart is left alone, its mirror image is not", "[inelastic][step:4:separating-pairs][points:2]") {
    RigidBody left = ball(1.0, {-0.45, 0, 0}, {-2, 0, 0});
    RigidBody right = ball(1.0, {0.45, 0, 0}, {1, 0, 0});
    const std::string apart = pair_text(right, left);
    inelastic::resolve(right, left, contact_between(right, left));
    expect_close(laws::separating, Vector3{1, 0, 0}, right.velocity, 0.0, "m/s", apart + " (body 1 after)");
    expect_close(laws::separating, Vector3{-2, 0, 0}, left.velocity, 0.0, "m/s", apart + " (body 2 after)");

    left.velocity = {2, 0, 0};
    right.velocity = {-1, 0, 0};
    const std::string towards = pair_text(right, left);
    const Contact contact = contact_between(right, left);
    inelastic::resolve(right, left, contact);
    // Checked with step 4's own law, so that a step 2 mistake is not reported here as well.
    workbook::testing::expect_at_least(laws::approach, 0.0, dot(right.velocity - left.velocity, contact.normal), 1e-12,
                                       "m/s", towards + " (approaching: normal relative velocity after)");
}

TEST_CASE("energy lost by a 2 kg cart at 3 m/s hitting a 1 kg cart at rest", "[inelastic][step:5:energy-lost][points:2]") {
    const RigidBody cart1 = ball(2.0, {0, 0, 0}, {3, 0, 0});
    const RigidBody cart2 = ball(1.0, {0.9, 0, 0}, {0, 0, 0});
    expect_close(laws::energy, 3.0, inelastic::energy_lost(cart1, cart2), 1e-12, "J", pair_text(cart1, cart2));
}

TEST_CASE("energy lost matches the kinetic energy that disappears", "[inelastic][step:5:energy-lost][points:2]") {
    const RigidBody body1 = ball(0.5, {0, 0, 0}, {1, 2, -3});
    const RigidBody body2 = ball(4.0, {0.3, 0.3, 0.3}, {-2, 0.5, 1});
    const double mu = body1.mass() * body2.mass() / (body1.mass() + body2.mass());
    const double expected = 0.5 * mu * length_squared(body1.velocity - body2.velocity);
    expect_close(laws::energy, expected, inelastic::energy_lost(body1, body2), 1e-12, "J", pair_text(body1, body2));
    const RigidBody wall = make_immovable_sphere(1.0, {2, 0, 0});
    expect_close(laws::energy, kinetic_energy(body1), inelastic::energy_lost(body1, wall), 1e-12, "J",
                 pair_text(body1, wall) + " (against a wall all kinetic energy is lost)");
}
