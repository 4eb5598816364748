// Detection with boxes: box-plane, sphere-box and box-box (separating axes and face clipping).
// Hand-worked poses pin the points and depths; seeded random poses check the laws every
// contact must obey: each point lies in both bodies within half its depth (points sit
// halfway between the surfaces), the penetration is the overlap of the two shadows on the
// normal, and swapping the bodies flips the normal and keeps the points.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "checks.hpp"
#include "seeded_random.hpp"
#include "workbook/box_detection.hpp"
#include "workbook/detection.hpp"
#include "workbook/tolerances.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double pi = std::numbers::pi;

Quaternion turn(const Vector3& axis, double degrees) { return from_axis_angle(normalized(axis), degrees * pi / 180.0); }

std::array<Vector3, 3> axes_of(const RigidBody& box) {
    const Matrix3 r = to_matrix(box.orientation);
    return {r.column(0), r.column(1), r.column(2)};
}

std::array<double, 3> halves_of(const RigidBody& box) {
    return {box.shape.half_extents.x, box.shape.half_extents.y, box.shape.half_extents.z};
}

/// Half the box's extent along the unit direction n.
double shadow_radius(const RigidBody& box, const Vector3& n) {
    const auto axes = axes_of(box);
    const auto h = halves_of(box);
    double r = 0.0;
    for (std::size_t k = 0; k < 3; ++k) r += h[k] * std::abs(dot(axes[k], n));
    return r;
}

/// Half the shadow of a sphere or a box on the unit direction n.
double shadow_radius_of(const RigidBody& body, const Vector3& n) {
    return body.shape.kind == ShapeKind::box ? shadow_radius(body, n) : body.shape.radius;
}

/// The overlap of the two bodies' shadows on the normal n (from body 2 towards body 1): how
/// far body 2 reaches along n past the lowest point of body 1.
double shadow_overlap(const RigidBody& body1, const RigidBody& body2, const Vector3& n) {
    return shadow_radius_of(body1, n) + shadow_radius_of(body2, n) - dot(body1.position - body2.position, n);
}

/// How far the point lies outside the body (0 inside or on its surface).
double distance_outside(const RigidBody& body, const Vector3& p) {
    if (body.shape.kind == ShapeKind::sphere) return std::max(length(p - body.position) - body.shape.radius, 0.0);
    if (body.shape.kind == ShapeKind::plane)
        return std::max(dot(p - body.position, rotate(body.orientation, body.shape.normal)), 0.0);
    const auto axes = axes_of(body);
    const auto h = halves_of(body);
    double squared = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double beyond = std::abs(dot(p - body.position, axes[k])) - h[k];
        if (beyond > 0.0) squared += beyond * beyond;
    }
    return std::sqrt(squared);
}

double size_of(const RigidBody& body) {
    if (body.shape.kind == ShapeKind::sphere) return body.shape.radius;
    const Vector3& h = body.shape.half_extents;
    return std::max({h.x, h.y, h.z, 0.0});
}

/// The laws every contact obeys, whatever the pose.
void check_contact_laws(const RigidBody& body1, const RigidBody& body2, const Contact& contact) {
    const double size = std::max(size_of(body1), size_of(body2));
    const double tolerance = 1e-12 * size;
    // Between two boxes a corner lying on the other's face to within tolerances::resting_corner
    // touches it, as a point of depth 0 halfway between the surfaces: outside either box by at
    // most half that distance.
    const bool boxes = body1.shape.kind == ShapeKind::box && body2.shape.kind == ShapeKind::box;
    const double touching = boxes ? tolerances::resting_corner * size : 0.0;
    CHECK_THAT(length(contact.normal), WithinAbs(1.0, 8 * eps));
    REQUIRE(contact.point_count >= 1);
    REQUIRE(contact.point_count <= max_contact_points);
    if (body2.shape.kind != ShapeKind::plane) {
        // A sphere whose centre lies outside the box takes as normal the direction from the
        // box's nearest point to its centre: a difference of two nearly equal points when the
        // centre is near the surface, whose direction holds only to about eps L / d (L the
        // size of the coordinates, d the centre's distance from the box). The shadows along
        // that normal move by the shapes' reach times that; the depth itself, r - d, does not.
        double normal_error = 0.0;
        if (body1.shape.kind == ShapeKind::sphere && body2.shape.kind == ShapeKind::box) {
            const double outside = body1.shape.radius - contact.penetration;
            const double coordinates = length(body1.position) + length(body2.position) + length(body2.shape.half_extents);
            if (outside > 0.0) {
                const double reach = length(body2.shape.half_extents) + length(body1.position - body2.position);
                normal_error = 8 * eps * coordinates / outside * reach;
            }
        }
        CHECK_THAT(contact.penetration,
                   WithinAbs(std::max(shadow_overlap(body1, body2, contact.normal), 0.0), tolerance + normal_error));
    }
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const ContactPoint& point = contact.points[i];
        CAPTURE(i, point.position, point.penetration, contact.normal);
        CHECK(point.penetration >= 0.0);
        CHECK((point.penetration > 0.0 || boxes));
        CHECK(point.penetration <= contact.penetration + tolerance);
        // Halfway between the surfaces: outside either body by at most half the point's depth.
        const double room = point.penetration > 0.0 ? point.penetration / 2 : touching / 2;
        CHECK(distance_outside(body1, point.position) <= room + tolerance);
        CHECK(distance_outside(body2, point.position) <= room + tolerance);
    }
}

/// How deep the deepest corner of `box` lies inside `other` (negative when none is inside).
double deepest_corner_inside(const RigidBody& box, const RigidBody& other) {
    const auto axes = axes_of(box);
    const auto h = halves_of(box);
    const auto other_axes = axes_of(other);
    const auto other_h = halves_of(other);
    double deepest = -std::numeric_limits<double>::infinity();
    for (int corner = 0; corner < 8; ++corner) {
        Vector3 p = box.position;
        for (std::size_t k = 0; k < 3; ++k) p += axes[k] * (((corner >> k) & 1) != 0 ? h[k] : -h[k]);
        double inside = std::numeric_limits<double>::infinity();  // distance to the nearest face
        for (std::size_t k = 0; k < 3; ++k)
            inside = std::min(inside, other_h[k] - std::abs(dot(p - other.position, other_axes[k])));
        deepest = std::max(deepest, inside);
    }
    return deepest;
}

/// Whether every point of `a` has a point of `b` within `tolerance` and the counts agree.
bool same_points(const Contact& a, const Contact& b, double tolerance) {
    if (a.point_count != b.point_count) return false;
    for (std::size_t i = 0; i < a.point_count; ++i) {
        bool found = false;
        for (std::size_t j = 0; j < b.point_count; ++j)
            found = found || (length(a.points[i].position - b.points[j].position) <= tolerance &&
                              std::abs(a.points[i].penetration - b.points[j].penetration) <= tolerance);
        if (!found) return false;
    }
    return true;
}

/// The point of `contact` nearest to `p`, to compare hand-worked points in any order.
const ContactPoint& nearest_point(const Contact& contact, const Vector3& p) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < contact.point_count; ++i)
        if (length(contact.points[i].position - p) < length(contact.points[best].position - p)) best = i;
    return contact.points[best];
}

void check_points(const Contact& contact, const std::vector<Vector3>& expected, double depth, double tolerance) {
    REQUIRE(contact.point_count == expected.size());
    for (const Vector3& p : expected) {
        const ContactPoint& found = nearest_point(contact, p);
        CHECK_THAT(found.position, is_close_to(p, tolerance));
        CHECK_THAT(found.penetration, WithinAbs(depth, tolerance));
    }
}

Quaternion random_orientation(testing::SeededRandom& random) {
    const Vector3 axis = random.direction();  // one draw a statement: the same poses on every compiler
    const double angle = random.uniform(0.0, 2 * pi);
    return normalized(from_axis_angle(axis, angle));
}

const RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});

}  // namespace

TEST_CASE("box-plane: a box resting flat touches at its four bottom corners", "[detection][box]") {
    // Half extents (0.5, 0.25, 0.3), bottom face 0.01 below the ground.
    const RigidBody box = make_box(2.0, {0.5, 0.25, 0.3}, {1.0, 0.24, -2.0});
    Contact contact;
    REQUIRE(collide_box_plane(box, ground, contact));
    CHECK(contact.normal == Vector3{0, 1, 0});
    CHECK_THAT(contact.penetration, WithinAbs(0.01, 4 * eps));
    // Each point halfway between its corner (y = -0.01) and the ground (y = 0).
    check_points(contact, {{0.5, -0.005, -2.3}, {1.5, -0.005, -2.3}, {0.5, -0.005, -1.7}, {1.5, -0.005, -1.7}}, 0.01,
                 8 * eps);
    check_contact_laws(box, ground, contact);
}

TEST_CASE("box-plane: a box on its edge touches at the edge's two ends", "[detection][box]") {
    // A unit cube turned 45 degrees about z stands on its edge along z, which reaches down
    // sqrt(2)/2 below the centre.
    const RigidBody box = make_box(1.0, {0.5, 0.5, 0.5}, {0.0, std::sqrt(0.5) - 0.01, 0.0}, turn({0, 0, 1}, 45));
    Contact contact;
    REQUIRE(collide_box_plane(box, ground, contact));
    CHECK_THAT(contact.penetration, WithinAbs(0.01, 1e-15));
    check_points(contact, {{0, -0.005, 0.5}, {0, -0.005, -0.5}}, 0.01, 1e-15);
    check_contact_laws(box, ground, contact);
}

TEST_CASE("box-plane: a box on its corner touches at one point", "[detection][box]") {
    // Turn the cube's body diagonal (1, 1, 1) onto the world y axis: the corner -(0.5, 0.5, 0.5)
    // is then lowest, sqrt(3)/2 below the centre; the next corners are sqrt(3)/6 below it.
    const Vector3 diagonal = normalized(Vector3{1, 1, 1});
    const Vector3 up{0, 1, 0};
    const Quaternion q = from_axis_angle(normalized(cross(diagonal, up)), std::acos(dot(diagonal, up)));
    const RigidBody box = make_box(1.0, {0.5, 0.5, 0.5}, {0.0, std::sqrt(3.0) / 2 - 0.01, 0.0}, q);
    Contact contact;
    REQUIRE(collide_box_plane(box, ground, contact));
    check_points(contact, {{0, -0.005, 0}}, 0.01, 1e-15);
    check_contact_laws(box, ground, contact);
}

TEST_CASE("box-plane: a box sunk deep keeps four corners: the deepest and the widest spread", "[detection][box]") {
    // Tilted 10 degrees about z and sunk to its centre: four bottom corners and two of the top
    // ones are below the ground, six candidates in all.
    const RigidBody box = make_box(1.0, {1.0, 0.25, 0.5}, {0.0, 0.0, 0.0}, turn({0, 0, 1}, 10));
    Contact contact;
    REQUIRE(collide_box_plane(box, ground, contact));
    REQUIRE(contact.point_count == 4);
    // The deepest corner is (1, -0.25, +-0.5) turned: depth sin(10) + 0.25 cos(10).
    const double deepest = std::sin(pi / 18) + 0.25 * std::cos(pi / 18);
    CHECK_THAT(contact.penetration, WithinAbs(deepest, 1e-15));
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) largest = std::max(largest, contact.points[i].penetration);
    CHECK(largest == contact.penetration);
    check_contact_laws(box, ground, contact);
    // The four kept span the whole length (2 m) and the whole width (1 m) of the box.
    double x_min = 1e9, x_max = -1e9, z_min = 1e9, z_max = -1e9;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        x_min = std::min(x_min, contact.points[i].position.x);
        x_max = std::max(x_max, contact.points[i].position.x);
        z_min = std::min(z_min, contact.points[i].position.z);
        z_max = std::max(z_max, contact.points[i].position.z);
    }
    CHECK(x_max - x_min > 1.9);
    CHECK_THAT(z_max - z_min, WithinAbs(1.0, 1e-15));
}

TEST_CASE("box-plane: no contact above the ground, and none when only touching", "[detection][box]") {
    Contact contact;
    CHECK_FALSE(collide_box_plane(make_box(1.0, {0.5, 0.25, 0.5}, {0, 0.3, 0}), ground, contact));
    CHECK_FALSE(collide_box_plane(make_box(1.0, {0.5, 0.25, 0.5}, {0, 0.25, 0}), ground, contact));
}

TEST_CASE("sphere-box: above a face, near an edge, and with the centre inside", "[detection][box]") {
    const RigidBody box = make_box(1.0, {1.0, 0.5, 1.0}, {0, 0, 0});
    Contact contact;
    SECTION("above the top face") {
        const RigidBody ball = make_sphere(1.0, 0.25, {0.3, 0.7, -0.2});
        REQUIRE(collide_sphere_box(ball, box, contact));
        CHECK(contact.normal == Vector3{0, 1, 0});
        CHECK_THAT(contact.penetration, WithinAbs(0.05, 4 * eps));
        check_points(contact, {{0.3, 0.475, -0.2}}, 0.05, 4 * eps);
        check_contact_laws(ball, box, contact);
    }
    SECTION("beside the edge x = 1, y = 0.5: the normal points from the edge to the centre") {
        const RigidBody ball = make_sphere(1.0, 0.25, {1.1, 0.6, 0.0});
        REQUIRE(collide_sphere_box(ball, box, contact));
        CHECK_THAT(contact.normal, is_close_to(normalized(Vector3{1, 1, 0}), 4 * eps));
        const double depth = 0.25 - 0.1 * std::sqrt(2.0);
        CHECK_THAT(contact.penetration, WithinAbs(depth, 4 * eps));
        check_points(contact, {Vector3{1, 0.5, 0} - contact.normal * (depth / 2)}, depth, 4 * eps);
        check_contact_laws(ball, box, contact);
    }
    SECTION("centre inside, nearest the top face: out through that face") {
        const RigidBody ball = make_sphere(1.0, 0.25, {0.0, 0.4, 0.0});
        REQUIRE(collide_sphere_box(ball, box, contact));
        CHECK(contact.normal == Vector3{0, 1, 0});
        CHECK_THAT(contact.penetration, WithinAbs(0.35, 4 * eps));
        check_points(contact, {{0, 0.325, 0}}, 0.35, 4 * eps);
        check_contact_laws(ball, box, contact);
    }
    SECTION("apart and touching: no contact") {
        CHECK_FALSE(collide_sphere_box(make_sphere(1.0, 0.25, {0, 0.8, 0}), box, contact));
        CHECK_FALSE(collide_sphere_box(make_sphere(1.0, 0.25, {0, 0.75, 0}), box, contact));
        CHECK_FALSE(collide_sphere_box(make_sphere(1.0, 0.25, {1.2, 0.7, 0}), box, contact));  // off the corner
    }
}

TEST_CASE("box-box: a small box turned about the normal rests on a big one at its four corners", "[detection][box]") {
    // The small box (half 0.3, 0.2, 0.3), turned 30 degrees about y, sits 0.02 deep in the top
    // face (y = 0.5) of the big one, well inside it: the points are its bottom corners at
    // y = 0.49, halfway between its bottom (0.48) and the big box's top.
    const RigidBody small = make_box(1.0, {0.3, 0.2, 0.3}, {0.1, 0.68, -0.1}, turn({0, 1, 0}, 30));
    const RigidBody big = make_box(5.0, {1.0, 0.5, 1.0}, {0, 0, 0});
    Contact contact;
    REQUIRE(collide_box_box(small, big, contact));
    CHECK_THAT(contact.normal, is_close_to(Vector3{0, 1, 0}, eps));
    CHECK_THAT(contact.penetration, WithinAbs(0.02, 1e-15));
    std::vector<Vector3> corners;
    for (const double sx : {-1.0, 1.0})
        for (const double sz : {-1.0, 1.0})
            corners.push_back(Vector3{0.1, 0.49, -0.1} + rotate(small.orientation, Vector3{0.3 * sx, 0, 0.3 * sz}));
    check_points(contact, corners, 0.02, 1e-15);
    check_contact_laws(small, big, contact);

    Contact swapped;
    REQUIRE(collide_box_box(big, small, swapped));
    CHECK(swapped.normal == -contact.normal);
    CHECK(swapped.penetration == contact.penetration);
    CHECK(same_points(swapped, contact, 1e-15));
}

TEST_CASE("box-box: equal boxes turned 45 degrees about the normal keep 4 of the 8 clipped corners", "[detection][box]") {
    // Two unit squares, one turned 45 degrees, overlap in a regular octagon of inradius 0.5
    // (area 2 tan(22.5 degrees) = 0.828 m^2). The best four of its corners are alternate ones, a
    // square of area 2 R^2 with R = 0.5 / cos(22.5 degrees): 0.586 m^2.
    const RigidBody upper = make_box(1.0, {0.5, 0.5, 0.5}, {0, 0.99, 0}, turn({0, 1, 0}, 45));
    const RigidBody lower = make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0});
    Contact contact;
    REQUIRE(collide_box_box(upper, lower, contact));
    CHECK_THAT(contact.normal, is_close_to(Vector3{0, 1, 0}, eps));
    REQUIRE(contact.point_count == 4);
    check_contact_laws(upper, lower, contact);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK_THAT(contact.points[i].penetration, WithinAbs(0.01, 1e-15));
        CHECK_THAT(contact.points[i].position.y, WithinAbs(0.495, 1e-15));
    }
    // The area of the kept quadrilateral, from its hull: largest of the three orderings.
    const auto& p = contact.points;
    const auto diagonal_area = [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) {
        return std::abs(cross(c - a, d - b).y) / 2;
    };
    const double area = std::max({diagonal_area(p[0].position, p[1].position, p[2].position, p[3].position),
                                  diagonal_area(p[0].position, p[1].position, p[3].position, p[2].position),
                                  diagonal_area(p[0].position, p[2].position, p[1].position, p[3].position)});
    const double circumradius = 0.5 / std::cos(pi / 8);
    CHECK_THAT(area, WithinAbs(2 * circumradius * circumradius, 1e-14));

    // Eight equally deep points and two equal faces: swapped, the same four are kept.
    Contact swapped;
    REQUIRE(collide_box_box(lower, upper, swapped));
    CHECK(swapped.normal == -contact.normal);
    CHECK(same_points(swapped, contact, 1e-15));
}

TEST_CASE("box-box: crossing edges touch at one point between the edges", "[detection][box]") {
    // The upper cube, turned 45 degrees about x, has its lowest edge along x at y = h - sqrt(2)/2;
    // the lower cube, turned 45 degrees about z, its highest edge along z at y = sqrt(2)/2. With
    // h = sqrt(2) - 0.1 they cross 0.1 deep, at the point halfway: (0, h/2, 0).
    const double h = std::sqrt(2.0) - 0.1;
    const RigidBody upper = make_box(1.0, {0.5, 0.5, 0.5}, {0, h, 0}, turn({1, 0, 0}, 45));
    const RigidBody lower = make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0}, turn({0, 0, 1}, 45));
    Contact contact;
    REQUIRE(collide_box_box(upper, lower, contact));
    CHECK_THAT(contact.normal, is_close_to(Vector3{0, 1, 0}, 4 * eps));  // x cross z: an edge axis, no face's
    CHECK_THAT(contact.penetration, WithinAbs(0.1, 1e-15));
    check_points(contact, {{0, h / 2, 0}}, 0.1, 1e-15);
    check_contact_laws(upper, lower, contact);

    Contact swapped;
    REQUIRE(collide_box_box(lower, upper, swapped));
    CHECK(swapped.normal == -contact.normal);
    CHECK(same_points(swapped, contact, 1e-15));
}

TEST_CASE("box-box: a cube on its edge on a big box touches along that edge", "[detection][box]") {
    const RigidBody cube = make_box(1.0, {0.5, 0.5, 0.5}, {0.2, 0.5 + std::sqrt(0.5) - 0.01, 0.1}, turn({0, 0, 1}, 45));
    const RigidBody big = make_box(5.0, {2.0, 0.5, 2.0}, {0, 0, 0});
    Contact contact;
    REQUIRE(collide_box_box(cube, big, contact));
    CHECK_THAT(contact.normal, is_close_to(Vector3{0, 1, 0}, eps));
    check_points(contact, {{0.2, 0.495, 0.6}, {0.2, 0.495, -0.4}}, 0.01, 1e-15);
    check_contact_laws(cube, big, contact);
}

TEST_CASE("box-box: a box resting on a box keeps its four corners while they lie on the face below",
          "[detection][box]") {
    // Two 20 cm cubes, the upper one built exactly on the lower (its centre at 0.1 + 0.2, which
    // rounding puts a few 1e-17 m off): they touch, and all four corners are points of depth 0.
    const RigidBody lower = make_box(1.0, {0.1, 0.1, 0.1}, {0, 0, 0.1});
    Contact contact;
    REQUIRE(collide_box_box(make_box(1.0, {0.1, 0.1, 0.1}, {0, 0, 0.1 + 0.2}), lower, contact));
    CHECK_THAT(contact.normal, is_close_to(Vector3{0, 0, 1}, eps));
    check_points(contact, {{-0.1, -0.1, 0.2}, {0.1, -0.1, 0.2}, {-0.1, 0.1, 0.2}, {0.1, 0.1, 0.2}}, 0.0, 1e-15);

    // Tilted by 1e-7 rad about x: the corners at y = -0.1 sink 1e-8 m into the face below, those
    // at y = +0.1 rise 1e-8 m in front of it. Those still touch (within resting_corner, 1e-6 m
    // for these boxes): four points, the raised two of depth 0, and nothing to turn about.
    const double hair = 1e-7;
    REQUIRE(collide_box_box(make_box(1.0, {0.1, 0.1, 0.1}, {0, 0, 0.3}, from_axis_angle({1, 0, 0}, hair)), lower, contact));
    REQUIRE(contact.point_count == 4);
    int raised = 0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double expected = contact.points[i].position.y < 0.0 ? 0.1 * std::sin(hair) : 0.0;
        CHECK_THAT(contact.points[i].penetration, WithinAbs(expected, 1e-15));  // rounding of 0.3: a few ulps
        raised += contact.points[i].penetration == 0.0 ? 1 : 0;
    }
    CHECK(raised == 2);

    // Tilted by 1e-4 rad, the raised corners stand 1e-5 m clear, ten times the tolerance: the
    // box rests on its lower edge, two points.
    REQUIRE(collide_box_box(make_box(1.0, {0.1, 0.1, 0.1}, {0, 0, 0.3}, from_axis_angle({1, 0, 0}, 1e-4)), lower, contact));
    CHECK(contact.point_count == 2);

    // Lifted 1e-6 m clear, far more than rounding: apart.
    CHECK_FALSE(collide_box_box(make_box(1.0, {0.1, 0.1, 0.1}, {0, 0, 0.3 + 1e-6}), lower, contact));
}

TEST_CASE("box-box: apart, or separated only along an edge axis, is no contact", "[detection][box]") {
    Contact contact;
    const RigidBody lower = make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0}, turn({0, 0, 1}, 45));
    CHECK_FALSE(collide_box_box(make_box(1.0, {0.5, 0.5, 0.5}, {0, 2, 0}), lower, contact));
    // The crossing cubes above, lifted 0.01 clear: every face axis still overlaps, only the
    // edge axis x cross z separates them.
    const RigidBody upper = make_box(1.0, {0.5, 0.5, 0.5}, {0, std::sqrt(2.0) + 0.01, 0}, turn({1, 0, 0}, 45));
    CHECK_FALSE(collide_box_box(upper, lower, contact));
}

TEST_CASE("speculative points: a pair with a box apart by less than the reach gets the points it would touch at, its gap as their depth",
          "[detection][box][speculative]") {
    // Each pair 0.01 apart: within a reach of 0.02 the points are written with depth -0.01 (to
    // the rounding of the positions, about 1); beyond a reach of 0.005, or with none, no contact.
    const double gap = 0.01, tolerance = 16 * eps;
    auto check_gap_points = [&](const Contact& contact, std::size_t count, const Vector3& normal) {
        CHECK(contact.point_count == count);
        CHECK_THAT(contact.normal, is_close_to(normal, tolerance));
        for (std::size_t i = 0; i < contact.point_count; ++i) CHECK_THAT(contact.points[i].penetration, WithinAbs(-gap, tolerance));
    };
    // Within the reach: `count` points at the gap; beyond a smaller reach, or with none: no contact.
    using Test = bool (*)(const RigidBody&, const RigidBody&, Contact&, double);
    auto check_pair = [&](Test collide_pair, const RigidBody& body1, const RigidBody& body2, std::size_t count) {
        Contact contact;
        REQUIRE(collide_pair(body1, body2, contact, 0.02));
        check_gap_points(contact, count, {0, 1, 0});
        CHECK_FALSE(collide_pair(body1, body2, contact, 0.005));
        CHECK_FALSE(collide_pair(body1, body2, contact, 0.0));
    };
    SECTION("a box above the ground: its four bottom corners") {
        check_pair(&collide_box_plane, make_box(2.0, {0.5, 0.25, 0.3}, {1.0, 0.25 + gap, -2.0}), ground, 4);
    }
    SECTION("a sphere above a face of a box: one point") {
        check_pair(&collide_sphere_box, make_sphere(1.0, 0.2, {0.1, 0.5 + 0.2 + gap, -0.1}), make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0}), 1);
    }
    SECTION("a cube above a cube, face to face: the four corners of the face") {
        check_pair(&collide_box_box, make_box(1.0, {0.5, 0.5, 0.5}, {0.2, 1.0 + gap, 0.1}), make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0}), 4);
    }
    SECTION("crossing cubes apart along an edge axis: one point between the edges") {
        check_pair(&collide_box_box, make_box(1.0, {0.5, 0.5, 0.5}, {0, std::sqrt(2.0) + gap, 0}, turn({1, 0, 0}, 45)),
                   make_box(1.0, {0.5, 0.5, 0.5}, {0, 0, 0}, turn({0, 0, 1}, 45)), 1);
    }
}

TEST_CASE("collide() dispatches pairs with a box: plane as body 2, otherwise in the order given", "[detection][box]") {
    const RigidBody box = make_box(1.0, {0.5, 0.5, 0.5}, {0, 0.4, 0});
    const RigidBody ball = make_sphere(1.0, 0.25, {0, 1.1, 0});
    const auto plane_first = collide(ground, 3, box, 7);
    REQUIRE(plane_first.has_value());
    CHECK(plane_first->body1 == 7);
    CHECK(plane_first->body2 == 3);
    CHECK(plane_first->normal == Vector3{0, 1, 0});
    CHECK(plane_first->point_count == 4);

    const auto ball_first = collide(ball, 1, box, 2);
    const auto box_first = collide(box, 2, ball, 1);
    REQUIRE(ball_first.has_value());
    REQUIRE(box_first.has_value());
    CHECK(ball_first->body1 == 1);
    CHECK(box_first->body1 == 2);
    CHECK(ball_first->normal == Vector3{0, 1, 0});
    CHECK(box_first->normal == Vector3{0, -1, 0});
    CHECK(same_points(*ball_first, *box_first, 0.0));

    const auto boxes = collide(box, 0, make_box(1.0, {0.5, 0.5, 0.5}, {0, -0.5, 0}), 1);
    REQUIRE(boxes.has_value());
    CHECK(boxes->body1 == 0);
    CHECK(boxes->body2 == 1);
    CHECK_FALSE(collide(box, 0, make_box(1.0, {0.5, 0.5, 0.5}, {0, 2, 0}), 1).has_value());
}

TEST_CASE("box-box, random poses: points in both boxes, depth = shadow overlap, swapping flips only the normal",
          "[detection][box][random]") {
    testing::SeededRandom random(testing::run_seed());
    int contacts = 0;
    std::array<int, max_contact_points + 1> by_count{};
    constexpr int cases = 2000;
    for (int n = 0; n < cases; ++n) {
        const Vector3 half_a{random.uniform(0.1, 1), random.uniform(0.1, 1), random.uniform(0.1, 1)};
        const Vector3 half_b{random.uniform(0.1, 1), random.uniform(0.1, 1), random.uniform(0.1, 1)};
        const Vector3 at_a = random.vector(1.0);
        const RigidBody a = make_box(1.0, half_a, at_a, random_orientation(random));
        const Vector3 at_b = random.vector(1.0);
        const RigidBody b = make_box(1.0, half_b, at_b, random_orientation(random));
        CAPTURE(n, a.position, a.orientation, half_a, b.position, b.orientation, half_b);
        Contact contact;
        Contact swapped;
        const bool touching = collide_box_box(a, b, contact);
        REQUIRE(collide_box_box(b, a, swapped) == touching);
        if (!touching) {
            // An independent witness against missed contacts: no corner of either box inside the other.
            CHECK(deepest_corner_inside(a, b) <= 0.0);
            CHECK(deepest_corner_inside(b, a) <= 0.0);
            continue;
        }
        ++contacts;
        ++by_count[contact.point_count];
        check_contact_laws(a, b, contact);
        CHECK(swapped.normal == -contact.normal);
        CHECK(swapped.penetration == contact.penetration);
        CHECK(same_points(swapped, contact, 1e-12));
    }
    // The poses must exercise the code: many contacts, of one, two and four points.
    CAPTURE(by_count[1], by_count[2], by_count[3], by_count[4]);
    CHECK(contacts > cases / 4);
    CHECK(by_count[1] > 0);
    CHECK(by_count[2] + by_count[3] + by_count[4] > 0);
}

TEST_CASE("box-box, random near-resting poses: face contacts obey the same laws", "[detection][box][random]") {
    // A box dropped a little into the top of another with a small tilt: the common case of
    // stacking, where the clipped faces give three or four points.
    testing::SeededRandom random(testing::run_seed() + 1);
    int four_points = 0;
    for (int n = 0; n < 500; ++n) {
        const Vector3 half_top{random.uniform(0.1, 0.6), random.uniform(0.1, 0.6), random.uniform(0.1, 0.6)};
        const RigidBody bottom = make_box(1.0, {1.0, 0.5, 1.0}, {0, 0, 0});
        const Vector3 tilt_axis = random.direction();
        const double tilt_angle = random.uniform(0.0, 0.05);
        const double heading = random.uniform(0, 360);
        const Quaternion tilt = normalized(from_axis_angle(tilt_axis, tilt_angle) * turn({0, 1, 0}, heading));
        const RigidBody top = make_box(1.0, half_top,
                                       {random.uniform(-0.8, 0.8), 0.5 + half_top.y - random.uniform(0.001, 0.05),
                                        random.uniform(-0.8, 0.8)},
                                       tilt);
        CAPTURE(n, top.position, top.orientation, half_top);
        Contact contact;
        if (!collide_box_box(top, bottom, contact)) continue;
        check_contact_laws(top, bottom, contact);
        if (contact.point_count == 4) ++four_points;
        Contact swapped;
        REQUIRE(collide_box_box(bottom, top, swapped));
        CHECK(swapped.normal == -contact.normal);
        CHECK(same_points(swapped, contact, 1e-12));
    }
    CHECK(four_points > 100);
}

TEST_CASE("sphere-box and box-plane, random poses: the same laws", "[detection][box][random]") {
    testing::SeededRandom random(testing::run_seed() + 2);
    int sphere_contacts = 0;
    int plane_contacts = 0;
    for (int n = 0; n < 1000; ++n) {
        const Vector3 half{random.uniform(0.1, 1), random.uniform(0.1, 1), random.uniform(0.1, 1)};
        const Vector3 box_at = random.vector(1.0);
        const RigidBody box = make_box(1.0, half, box_at, random_orientation(random));
        const double ball_radius = random.uniform(0.05, 1);
        const RigidBody ball = make_sphere(1.0, ball_radius, random.vector(1.5));
        CAPTURE(n, box.position, box.orientation, half, ball.position, ball.shape.radius);
        Contact contact;
        if (collide_sphere_box(ball, box, contact)) {
            ++sphere_contacts;
            check_contact_laws(ball, box, contact);
            const auto reversed = collide(box, 0, ball, 1);
            REQUIRE(reversed.has_value());
            CHECK(reversed->normal == -contact.normal);
            CHECK(same_points(*reversed, contact, 0.0));
        }
        const Vector3 plane_normal = random.direction();
        const RigidBody plane = make_immovable_plane(plane_normal, random.vector(0.5));
        if (collide_box_plane(box, plane, contact)) {
            ++plane_contacts;
            check_contact_laws(box, plane, contact);
            CHECK(contact.normal == plane_normal);
            // Depth: how far the box reaches behind the plane.
            const double behind = dot(plane.position - box.position, plane_normal) + shadow_radius(box, plane_normal);
            CHECK_THAT(contact.penetration, WithinAbs(behind, 1e-12));
            for (std::size_t i = 0; i < contact.point_count; ++i)  // halfway between corner and plane
                CHECK_THAT(dot(contact.points[i].position - plane.position, plane_normal),
                           WithinAbs(-contact.points[i].penetration / 2, 1e-12));
        }
    }
    CHECK(sphere_contacts > 100);
    CHECK(plane_contacts > 100);
}
