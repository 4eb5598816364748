// The swept test for fast spheres (engine/src/swept_spheres.cpp) moves a sphere that went
// through another back to where they touched. What it leaves at that place must be answered
// in the same step like any other overlap: the stress corpus's 100 g pile once pushed ball
// centres through the walls of its box because it was not.
#include <catch2/catch_test_macros.hpp>

#include <cmath>

#include "models.hpp"
#include "workbook/world.hpp"

using namespace workbook;

TEST_CASE("a sphere swept back to its partner, which has moved on since they touched, is pushed clear in the same step",
          "[accuracy][swept]") {
    // A 0.1 m ball at 360 m/s (1.5 m per step of 1/240 s) passes through a 0.1 m ball coming the
    // other way at 24 m/s and ends 0.3 m beyond it: tunnelling. They touched 0.6875 of the way
    // through the step, where the fast ball goes back to (x = 0.03125 m); the slow one is then
    // already at 0.2 m, 0.03125 m into it. Projection (fraction 1) must remove that overlap now.
    WorldSettings settings;  // discrete timing, swept spheres on
    const double r = 0.1;
    World world({make_sphere(1.0, r, {-1.0, 0, 0}, {360.0, 0, 0}), make_sphere(1.0, r, {0.3, 0, 0}, {-24.0, 0, 0})},
                settings, accuracy::chapter_model("linear-impulse"));
    world.step();
    const RigidBody& fast = world.bodies()[0];
    const RigidBody& slow = world.bodies()[1];
    INFO("fast ball at " << fast.position.x << " m, slow ball at " << slow.position.x << " m");
    CHECK(slow.position.x - fast.position.x >= 2.0 * r * (1.0 - 1e-12));
    // e = 1, equal masses: they swap velocities, and momentum is kept.
    CHECK(std::abs(fast.velocity.x - -24.0) <= 1e-12 * 360.0);
    CHECK(std::abs(slow.velocity.x - 360.0) <= 1e-12 * 360.0);
}

TEST_CASE("a sphere swept back into a place where it overlaps a third body is answered against it too", "[accuracy][swept]") {
    // The fast ball tunnels through a pinned ball; where it is moved back to, a third ball that
    // fell into that place during the step overlaps it. The contact with the third ball is found
    // at the new place, so both are pushed apart in the same step.
    WorldSettings settings;
    const double r = 0.1;
    World world({make_sphere(1.0, r, {-1.0, 0, 0}, {360.0, 0, 0}), make_immovable_sphere(r, {0.0, 0, 0}),
                 make_sphere(1.0, r, {-0.25, 0.9, 0}, {0.0, -180.0, 0})},
                settings, accuracy::chapter_model("linear-impulse"));
    world.step();
    const RigidBody& fast = world.bodies()[0];
    const RigidBody& third = world.bodies()[2];
    INFO("fast ball at (" << fast.position.x << ", " << fast.position.y << "), third ball at (" << third.position.x
                          << ", " << third.position.y << ")");
    CHECK(length(fast.position - third.position) >= 2.0 * r * (1.0 - 1e-12));
}

TEST_CASE("the touching contact of a swept sphere and a partner that moved on pushes both through their centres",
          "[accuracy][swept]") {
    // A 0.1 m ball at 120 m/s (2 m per step of 1/60 s) passes under a 0.1 m ball moving up at
    // 6 m/s: they touch about 0.48 of the way through the step, and at the end the slow ball is
    // 0.25 m clear of the place the fast one goes back to, so the contact of that moment is
    // the one answered. Frictionless balls: a push through both centres turns neither. With
    // the normal taken where the slow ball was when they touched and the lever arm where it
    // ended, the push spun both.
    WorldSettings settings;
    settings.time_step = 1.0 / 60.0;
    const double r = 0.1;
    for (const char* chapter : {"angular-impulse", "resting-contact"}) {
        CAPTURE(chapter);
        World world({make_sphere(1.0, r, {-1.0, 0, 0}, {120.0, 0, 0}), make_sphere(1.0, r, {0.0, 0.15, 0}, {0.0, 6.0, 0})},
                    settings, accuracy::chapter_model(chapter));
        world.step();
        const RigidBody& fast = world.bodies()[0];
        const RigidBody& slow = world.bodies()[1];
        INFO("fast ball at (" << fast.position.x << ", " << fast.position.y << "), slow ball at (" << slow.position.x
                              << ", " << slow.position.y << ")");
        // It was answered: the slow ball got a push along x.
        REQUIRE(slow.velocity.x > 0.1);
        // Lever arms along the normal: a spin of rounding only, a few ulps of v / r = 1200 rad/s.
        CHECK(length(fast.angular_velocity) <= 1e-12 * 120.0 / r);
        CHECK(length(slow.angular_velocity) <= 1e-12 * 120.0 / r);
        // Momentum is kept.
        CHECK(std::abs(fast.velocity.x + slow.velocity.x - 120.0) <= 1e-12 * 120.0);
        CHECK(std::abs(fast.velocity.y + slow.velocity.y - 6.0) <= 1e-12 * 120.0);
    }
}
