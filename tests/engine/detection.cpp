// Narrow-phase detection on cases small enough to work out by hand. The geometry uses
// 3-4-5 triangles and binary fractions, so most expected values are exact.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "checks.hpp"
#include "workbook/detection.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("sphere-sphere: normal from body 2 to body 1, depth r1 + r2 - d, point halfway", "[detection][sphere]") {
    // Centres 1.5 apart along (0.6, 0.8, 0); radii 1 and 0.75 overlap by 0.25.
    const RigidBody sphere1 = make_sphere(1.0, 1.0, {0.9, 1.2, 0.0});
    const RigidBody sphere2 = make_sphere(1.0, 0.75, {0.0, 0.0, 0.0});

    const auto contact = collide_spheres(sphere1, sphere2);
    REQUIRE(contact.has_value());
    CHECK_THAT(contact->normal, is_close_to(Vector3{0.6, 0.8, 0.0}, eps));
    CHECK_THAT(length(contact->normal), WithinAbs(1.0, 2 * eps));
    CHECK_THAT(contact->penetration, WithinAbs(0.25, 4 * eps));
    REQUIRE(contact->point_count == 1);
    CHECK(contact->points[0].penetration == contact->penetration);
    // Deepest point of sphere 1 is (0.3, 0.4, 0), of sphere 2 is (0.45, 0.6, 0).
    CHECK_THAT(contact->points[0].position, is_close_to(Vector3{0.375, 0.5, 0.0}, 4 * eps));
}

TEST_CASE("sphere-sphere: swapping the bodies flips the normal and keeps depth and point", "[detection][sphere]") {
    const RigidBody left = make_sphere(2.0, 0.5, {-0.4, 0.0, 0.0});
    const RigidBody right = make_sphere(3.0, 0.5, {0.4, 0.0, 0.0});

    const auto right_first = collide_spheres(right, left);
    const auto left_first = collide_spheres(left, right);
    REQUIRE(right_first.has_value());
    REQUIRE(left_first.has_value());
    CHECK(right_first->normal == Vector3{1, 0, 0});
    CHECK(left_first->normal == Vector3{-1, 0, 0});
    CHECK_THAT(right_first->penetration, WithinAbs(0.2, 2 * eps));
    CHECK(left_first->penetration == right_first->penetration);
    CHECK_THAT(right_first->points[0].position, is_close_to(Vector3{0, 0, 0}, 2 * eps));
    CHECK_THAT(left_first->points[0].position, is_close_to(Vector3{0, 0, 0}, 2 * eps));
}

TEST_CASE("sphere-sphere: the point is halfway between surfaces for unequal radii", "[detection][sphere]") {
    // Along z: sphere 2 (r = 2) at 0, sphere 1 (r = 0.5) at 2.25. Surfaces reach 2 and 1.75.
    const RigidBody small = make_sphere(1.0, 0.5, {0.0, 0.0, 2.25});
    const RigidBody big = make_sphere(1.0, 2.0, {0.0, 0.0, 0.0});
    const auto contact = collide_spheres(small, big);
    REQUIRE(contact.has_value());
    CHECK(contact->normal == Vector3{0, 0, 1});
    CHECK(contact->penetration == 0.25);
    CHECK(contact->points[0].position == Vector3{0, 0, 1.875});
}

TEST_CASE("sphere-sphere: touching without overlap is no contact", "[detection][sphere]") {
    const RigidBody sphere1 = make_sphere(1.0, 1.0, {2.0, 0.0, 0.0});
    const RigidBody sphere2 = make_sphere(1.0, 1.0, {0.0, 0.0, 0.0});
    CHECK_FALSE(collide_spheres(sphere1, sphere2).has_value());

    const RigidBody apart = make_sphere(1.0, 1.0, {3.0, 4.0, 0.0});
    CHECK_FALSE(collide_spheres(apart, sphere2).has_value());

    // A hair closer than touching does overlap, by that hair.
    const double gap = 1.0 / 1024.0;
    const RigidBody closer = make_sphere(1.0, 1.0, {2.0 - gap, 0.0, 0.0});
    const auto contact = collide_spheres(closer, sphere2);
    REQUIRE(contact.has_value());
    CHECK(contact->penetration == gap);
}

TEST_CASE("sphere-sphere: coincident centres give the fixed unit normal, never NaN", "[detection][sphere]") {
    const RigidBody sphere1 = make_sphere(1.0, 0.5, {1.0, 2.0, 3.0});
    const RigidBody sphere2 = make_sphere(1.0, 0.25, {1.0, 2.0, 3.0});
    const auto contact = collide_spheres(sphere1, sphere2);
    REQUIRE(contact.has_value());
    CHECK(contact->normal == coincident_centres_normal);
    CHECK(length(contact->normal) == 1.0);
    CHECK(is_finite(contact->normal));
    CHECK(contact->penetration == 0.75);
    CHECK(is_finite(contact->points[0].position));
    // Halfway between sphere 1's surface at p - 0.5 n and sphere 2's at p + 0.25 n.
    CHECK(contact->points[0].position == Vector3{1.0, 1.875, 3.0});
}

TEST_CASE("sphere-plane: depth r - height, normal is the plane's, point halfway", "[detection][plane]") {
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 1, 0});
    const RigidBody ball = make_sphere(1.0, 0.5, {2.0, 1.25, -1.0});

    const auto contact = collide_sphere_plane(ball, ground);
    REQUIRE(contact.has_value());
    CHECK(contact->normal == Vector3{0, 1, 0});
    CHECK(contact->penetration == 0.25);
    REQUIRE(contact->point_count == 1);
    // The ball reaches down to y = 0.75, the plane surface is at y = 1.
    CHECK(contact->points[0].position == Vector3{2.0, 0.875, -1.0});
}

TEST_CASE("sphere-plane: a tilted plane normal", "[detection][plane]") {
    const Vector3 n{0.6, 0.8, 0.0};
    const RigidBody wall = make_immovable_plane(n, {0, 0, 0});
    // Height 0.3 above the plane along n, radius 0.5.
    const RigidBody ball = make_sphere(1.0, 0.5, n * 0.3 + Vector3{0.8, -0.6, 0.0} * 7.0);

    const auto contact = collide_sphere_plane(ball, wall);
    REQUIRE(contact.has_value());
    CHECK(contact->normal == n);
    CHECK_THAT(contact->penetration, WithinAbs(0.2, 16 * eps));
    CHECK_THAT(contact->points[0].position, is_close_to(ball.position - n * 0.4, 16 * eps));
}

TEST_CASE("sphere-plane: the normal follows the plane body's orientation", "[detection][plane]") {
    // Body-space normal +y turned a quarter about z points along -x in the world.
    RigidBody wall = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    wall.orientation = from_axis_angle({0, 0, 1}, std::numbers::pi / 2);
    const RigidBody ball = make_sphere(1.0, 0.5, {-0.375, 2.0, 0.0});

    const auto contact = collide_sphere_plane(ball, wall);
    REQUIRE(contact.has_value());
    CHECK_THAT(contact->normal, is_close_to(Vector3{-1, 0, 0}, eps));
    CHECK_THAT(contact->penetration, WithinAbs(0.125, 2 * eps));
    CHECK_THAT(contact->points[0].position, is_close_to(Vector3{0.0625, 2.0, 0.0}, 2 * eps));
}

TEST_CASE("sphere-plane: a sphere entirely behind the plane is still a contact", "[detection][plane]") {
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    const RigidBody sunk = make_sphere(1.0, 0.5, {0.0, -3.0, 0.0});
    const auto contact = collide_sphere_plane(sunk, ground);
    REQUIRE(contact.has_value());
    CHECK(contact->normal == Vector3{0, 1, 0});
    CHECK(contact->penetration == 3.5);
    // Halfway between the sphere's lowest point, y = -3.5, and the plane surface, y = 0.
    CHECK(contact->points[0].position == Vector3{0.0, -1.75, 0.0});
}

TEST_CASE("sphere-plane: resting exactly on the plane or above it is no contact", "[detection][plane]") {
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    CHECK_FALSE(collide_sphere_plane(make_sphere(1.0, 0.5, {0.0, 0.5, 0.0}), ground).has_value());
    CHECK_FALSE(collide_sphere_plane(make_sphere(1.0, 0.5, {0.0, 7.0, 0.0}), ground).has_value());
}

TEST_CASE("collide: sphere first keeps the order and the indices", "[detection][dispatch]") {
    const RigidBody ball = make_sphere(1.0, 0.5, {0.0, 0.25, 0.0});
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    const auto contact = collide(ball, 3, ground, 7);
    REQUIRE(contact.has_value());
    CHECK(contact->body1 == 3);
    CHECK(contact->body2 == 7);
    CHECK(contact->normal == Vector3{0, 1, 0});
    CHECK(contact->penetration == 0.25);
}

TEST_CASE("collide: plane first swaps the bodies so the normal still points from body 2 to body 1",
          "[detection][dispatch]") {
    const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    const RigidBody ball = make_sphere(1.0, 0.5, {0.0, 0.25, 0.0});
    const auto contact = collide(ground, 2, ball, 5);
    REQUIRE(contact.has_value());
    CHECK(contact->body1 == 5);  // the sphere
    CHECK(contact->body2 == 2);  // the plane
    CHECK(contact->normal == Vector3{0, 1, 0});
    CHECK(contact->penetration == 0.25);
    CHECK(contact->points[0].position == Vector3{0.0, -0.125, 0.0});
}

TEST_CASE("collide: two spheres keep the order and the indices", "[detection][dispatch]") {
    const RigidBody sphere1 = make_sphere(1.0, 0.5, {0.0, 0.0, 0.0});
    const RigidBody sphere2 = make_sphere(1.0, 0.5, {0.0, 0.0, 0.75});
    const auto contact = collide(sphere1, 0, sphere2, 1);
    REQUIRE(contact.has_value());
    CHECK(contact->body1 == 0);
    CHECK(contact->body2 == 1);
    CHECK(contact->normal == Vector3{0, 0, -1});
    CHECK(contact->penetration == 0.25);
}

TEST_CASE("collide: pairs without a narrow phase give no contact", "[detection][dispatch]") {
    const RigidBody floor = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    const RigidBody wall = make_immovable_plane({1, 0, 0}, {0, 0, 0});
    CHECK_FALSE(collide(floor, 0, wall, 1).has_value());
    // Pairs with a box have their own narrow phase since chapter 4: see box_detection.cpp.
}

TEST_CASE("Contact::add_point keeps the deepest penetration and stops at capacity", "[detection][contact]") {
    Contact contact;
    contact.add_point({0, 0, 0}, 0.1);
    contact.add_point({1, 0, 0}, 0.3);
    contact.add_point({2, 0, 0}, 0.2);
    CHECK(contact.point_count == 3);
    CHECK(contact.penetration == 0.3);
    contact.add_point({3, 0, 0}, 0.0);
    contact.add_point({4, 0, 0}, 9.0);  // past max_contact_points: dropped, its depth too
    CHECK(contact.point_count == max_contact_points);
    CHECK(contact.penetration == 0.3);
    CHECK(contact.points[3].position == Vector3{3, 0, 0});
}
