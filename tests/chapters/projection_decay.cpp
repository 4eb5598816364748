// Ties chapter 2's claims about repeated projection to the engine itself: a World running only
// its detection and position stages on two overlapping balls. Each pass removes the fraction
// beta of the depth beyond the slop, so the depth is s + (d0 - s)(1 - beta)^k after k passes,
// while the centre of mass of the pair stays where it was, to rounding.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

using namespace workbook;

namespace {

/// Two 1 kg and 3 kg balls of radius 0.5 m, `depth` deep along a normal off every axis.
World overlapping_pair(double depth, PositionCorrection knobs) {
    const Vector3 normal = normalized(Vector3{1, 2, 2});
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.5, normal * (1.0 - depth)), make_sphere(3.0, 0.5, {0, 0, 0})};
    WorldSettings settings;
    settings.position_correction = knobs;
    return World(std::move(bodies), settings, *find_response_model("projection"));
}

double depth_of(const World& world) { return 1.0 - length(world.bodies()[0].position - world.bodies()[1].position); }

Vector3 centre_of_mass(const World& world) {
    return (1.0 * world.bodies()[0].position + 3.0 * world.bodies()[1].position) / 4.0;
}

}  // namespace

TEST_CASE("Repeated projection passes leave s + (d0 - s)(1 - beta)^k of the depth, centre of mass fixed", "[projection]") {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();
    const double d0 = 0.1;
    const double slop = 0.005;
    for (const double beta : {0.2, 0.5, 0.8, 1.0}) {
        World world = overlapping_pair(d0, {beta, slop});
        const Vector3 centre = centre_of_mass(world);
        for (int k = 1; k <= 12; ++k) {
            world.detect();
            world.correct();
            INFO("beta " << beta << ", pass " << k);
            CHECK(std::abs(depth_of(world) - (slop + (d0 - slop) * std::pow(1.0 - beta, k))) <= 64 * epsilon);
            CHECK(length(centre_of_mass(world) - centre) <= 16 * epsilon);
        }
    }
}

TEST_CASE("With beta 1.5 one pass overshoots into a gap of (beta - 1)(d0 - s) - s, which later passes leave alone", "[projection]") {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();
    const double d0 = 0.1;
    const double slop = 0.005;
    World world = overlapping_pair(d0, {1.5, slop});
    const Vector3 centre = centre_of_mass(world);
    for (int k = 1; k <= 3; ++k) {
        world.detect();
        world.correct();
        INFO("pass " << k);
        // The first pass finds the contact; after it the balls no longer touch.
        CHECK(world.contacts().size() == (k == 1 ? 1U : 0U));
        CHECK(std::abs(depth_of(world) - (slop - 0.5 * (d0 - slop))) <= 64 * epsilon);
        CHECK(length(centre_of_mass(world) - centre) <= 16 * epsilon);
    }
}

TEST_CASE("A ball in a corner: one pass clears a square corner, not an acute one (the page's several-contacts section)", "[projection]") {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();
    const auto one_pass = [](const Vector3& wall_normal) {
        // A ball of radius 0.5 m at (0, 0.45, 0): 5 cm into the floor and 5 cm into the wall.
        const Vector3 wall_point = Vector3{0, 0.45, 0} - wall_normal * 0.45;
        std::vector<RigidBody> bodies{make_sphere(1.0, 0.5, {0, 0.45, 0}), make_immovable_plane({0, 1, 0}, {0, 0, 0}),
                                      make_immovable_plane(wall_normal, wall_point)};
        World world(std::move(bodies), WorldSettings{}, *find_response_model("projection"));
        world.detect();
        REQUIRE(world.contacts().size() == 2);
        world.correct();
        world.detect();
        return world;
    };
    // Square corner: the normals are at right angles, the pushes do not interfere.
    const World square = one_pass({1, 0, 0});
    CHECK(square.contacts().empty());
    CHECK(std::abs(square.bodies()[0].position.x - 0.05) <= 4 * epsilon);
    CHECK(std::abs(square.bodies()[0].position.y - 0.5) <= 4 * epsilon);
    // A wall leaning over the floor (normals 120 degrees apart): the pushes partly cancel and
    // the ball still overlaps both surfaces after the pass.
    const World acute = one_pass(normalized(Vector3{std::sqrt(3.0), -1.0, 0}));
    CHECK(acute.contacts().size() == 2);
    // A wider corner (normals 60 degrees apart): the pushes reinforce each other and the ball
    // ends up clear of the floor with a gap, pushed out too far.
    const World wide = one_pass(normalized(Vector3{std::sqrt(3.0), 1.0, 0}));
    CHECK(wide.contacts().empty());
    CHECK(wide.bodies()[0].position.y > 0.5 + 0.01);
}
