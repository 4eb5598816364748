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
