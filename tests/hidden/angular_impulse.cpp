// Hidden step tests for chapter 4, angular impulses: the same steps and laws as the public
// tests, on other numbers, random poses and the corner cases a shortcut misses.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "angular-impulse.hpp"
#include "../steps/angular_impulse_bodies.hpp"
#include "../steps/angular_impulse_laws.hpp"
#include "feedback.hpp"
#include "sent_values.hpp"
#include "seeded_random.hpp"

using namespace workbook;
using namespace workbook::angular_impulse_cases;
namespace laws = workbook::angular_impulse_laws;
using workbook::testing::expect_at_least;
using workbook::testing::expect_close;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

constexpr double degrees = std::numbers::pi / 180.0;

void expect_matrix(const testing::Law& law, const Matrix3& expected, const Matrix3& actual, double tolerance,
                   const std::string& situation) {
    for (int c = 0; c < 3; ++c)
        expect_close(law, expected.column(c), actual.column(c), tolerance, "1/(kg m^2)", situation + " (column " + std::to_string(c) + ")");
}

/// A box resting flat on the ground (z = 0), turned by `yaw` about z, its four lower corners.
struct FlatLanding {
    RigidBody box;
    Contact contact;
    FlatLanding(double mass, const Vector3& half, double yaw, double speed, double e) {
        const Quaternion turn = from_axis_angle({0, 0, 1}, yaw);
        box = make_box(mass, half, {0.3, -0.2, half.z}, turn, {0, 0, -speed});
        box.restitution = e;
        contact.normal = {0, 0, 1};
        for (const Vector3 corner : {Vector3{-1, -1, -1}, Vector3{1, -1, -1}, Vector3{1, 1, -1}, Vector3{-1, 1, -1}})
            contact.add_point(box.position + rotate(turn, Vector3{corner.x * half.x, corner.y * half.y, corner.z * half.z}), 1e-3);
    }
};

}  // namespace

TEST_CASE("random orientations: I_world^-1 is the inverse of R I R^T", "[angular-impulse][step:1:world-inverse-inertia][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 40; ++i) {
        const Vector3 box_centre = random.vector(3.0);
        const RigidBody box = random_box(random, box_centre);
        const Matrix3 product = angular_impulse::world_inverse_inertia(box) * box.inertia_world();
        expect_matrix(laws::world_inertia, Matrix3::identity(), product, 1e-11, describe_body(box) + " (I_world^-1 times R I R^T)");
    }
}

TEST_CASE("a box turned 90 degrees about x swaps its y and z moments; a moving platform is not turned",
          "[angular-impulse][step:1:world-inverse-inertia][points:2]") {
    const RigidBody box = make_box(3.0, {0.5, 1.0, 2.0}, {-2, 0, 1}, from_axis_angle({1, 0, 0}, 90.0 * degrees));
    const double ix = 1.0 * (1.0 + 4.0), iy = 1.0 * (0.25 + 4.0), iz = 1.0 * (0.25 + 1.0);
    expect_matrix(laws::world_inertia, Matrix3::diagonal({1.0 / ix, 1.0 / iz, 1.0 / iy}), angular_impulse::world_inverse_inertia(box),
                  rounding_tolerance(1.0, 64), describe_body(box));
    RigidBody platform = make_immovable_sphere(1.0, {0, 0, 0});
    platform.velocity = {1, 0, 0};
    platform.angular_velocity = {0, 0, 1};
    platform.orientation = from_axis_angle({0, 1, 1}, 0.5);
    expect_matrix(laws::immovable, Matrix3::zero(), angular_impulse::world_inverse_inertia(platform), 0.0, describe_body(platform));
}

TEST_CASE("random bodies and points: v + w x r from the body's own centre", "[angular-impulse][step:2:point-velocity][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 40; ++i) {
        const Vector3 body_centre = random.vector(10.0);
        const RigidBody body = random_box(random, body_centre);
        const Vector3 p = body.position + random.vector(2.0);
        const Vector3 expected = body.velocity + cross(body.angular_velocity, p - body.position);
        expect_close(laws::point_velocity, expected, angular_impulse::point_velocity(body, p), rounding_tolerance(20.0, 64), "m/s",
                     describe_body(body) + "; point " + format(p) + " m");
    }
}

TEST_CASE("the centre moves with v exactly; a point on the spin axis too", "[angular-impulse][step:2:point-velocity][points:2]") {
    RigidBody wheel = make_sphere(1.0, 0.5, {5, 5, 0}, {1, -2, 0.5});
    wheel.angular_velocity = {0, 0, 10};
    expect_close(laws::point_velocity, wheel.velocity, angular_impulse::point_velocity(wheel, wheel.position), 0.0, "m/s",
                 describe_body(wheel) + "; the centre");
    expect_close(laws::point_velocity, wheel.velocity, angular_impulse::point_velocity(wheel, {5, 5, 0.5}), 0.0, "m/s",
                 describe_body(wheel) + "; the top, on the spin axis");
    expect_close(laws::point_velocity, Vector3{-4, -2, 0.5}, angular_impulse::point_velocity(wheel, {5, 5.5, 0}), rounding_tolerance(5.0),
                 "m/s", describe_body(wheel) + "; the rim at (5, 5.5, 0)");
}

TEST_CASE("rods at many tilts and restitutions: J = (1 + e) m u / (1 + 3 cos^2 theta)", "[angular-impulse][step:3:impulse-size][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    const RigidBody floor = ground();
    for (int i = 0; i < 30; ++i) {
        const double mass = random.log_uniform(-1, 2);
        const double length = random.uniform(0.2, 3.0);
        const double theta = random.uniform(0.0, 89.0) * degrees;
        const double speed = random.uniform(0.1, 10.0);
        const double e = random.uniform(0.0, 1.0);
        const RigidBody rod = thin_rod(mass, length, theta, {1, 2, 3}, {0, 0, -speed});
        const double c = std::cos(theta);
        const double expected = (1.0 + e) * mass * speed / (1.0 + 3.0 * c * c);
        expect_close(laws::rod, expected, angular_impulse::impulse_magnitude(rod, floor, rod_lower_end(rod, length), {0, 0, 1}, e),
                     1e-9 * expected, "N s",
                     "rod m = " + format(mass) + " kg, L = " + format(length) + " m, theta = " + format(theta / degrees) +
                         " deg, u = " + format(speed) + " m/s, e = " + format(e));
    }
}

TEST_CASE("the ground as body 1, a two-wall pair, and a central hit", "[angular-impulse][step:3:impulse-size][points:2]") {
    const double mass = 2.0, length = 1.0, theta = 45.0 * degrees, speed = 2.0, e = 0.3;
    const RigidBody rod = thin_rod(mass, length, theta, {0, 0, 0}, {0, 0, -speed});
    const RigidBody floor = ground();
    const double expected = (1.0 + e) * mass * speed / 2.5;
    // Body order swapped: the normal now points from the rod (body 2) to the ground (body 1).
    expect_close(laws::rod, expected, angular_impulse::impulse_magnitude(floor, rod, rod_lower_end(rod, length), {0, 0, -1}, e),
                 1e-9 * expected, "N s", "ground as body 1, rod (m = 2 kg, L = 1 m, 45 deg, 2 m/s) as body 2, n = (0, 0, -1)");
    const RigidBody wall1 = make_immovable_sphere(1.0, {0, 0, 0});
    RigidBody wall2 = make_immovable_sphere(1.0, {2, 0, 0});
    wall2.velocity = {-1, 0, 0};
    expect_close(laws::immovable, 0.0, angular_impulse::impulse_magnitude(wall1, wall2, {1, 0, 0}, {-1, 0, 0}, 0.5), 0.0, "N s",
                 "two immovable balls, one moving into the other");
    const RigidBody heavy = make_sphere(1e6, 1.0, {0, 0, 0}, {0, 0, -1});
    const RigidBody light = make_sphere(1e-3, 0.1, {0, 0, -1.1}, {0, 0, 1});
    const double u = -2.0;
    const double central = -(1.0 + 0.9) * u / (heavy.inverse_mass + light.inverse_mass);
    expect_close(laws::central, central, angular_impulse::impulse_magnitude(heavy, light, {0, 0, -1.0}, {0, 0, 1}, 0.9),
                 rounding_tolerance(central), "N s", pair_text(heavy, light) + "\ncentral hit, e = 0.9");
}

TEST_CASE("random off-centre pairs: J against the law of restitution and the free rod", "[angular-impulse][step:3:impulse-size][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 40; ++i) {
        const Vector3 a_centre = random.vector(1.0);
        RigidBody a = random_box(random, a_centre);
        const Vector3 b_centre = random.vector(1.0);
        RigidBody b = random_box(random, b_centre);
        const Vector3 n = random.direction();
        const Vector3 p = random.vector(1.0);
        const double u = normal_velocity_at(a, b, p, n);
        const double e = random.uniform(0.0, 1.0);
        const std::string situation = pair_text(a, b) + "\npoint " + format(p) + " m, n = " + format(n) + ", e = " + format(e);
        const double j = angular_impulse::impulse_magnitude(a, b, p, n, e);
        a.velocity += a.inverse_mass * j * n;
        a.angular_velocity += inverse(a.inertia_world()) * cross(p - a.position, j * n);
        b.velocity -= b.inverse_mass * j * n;
        b.angular_velocity -= inverse(b.inertia_world()) * cross(p - b.position, j * n);
        const double scale = 3.0 * (length(a.velocity) + length(b.velocity) + length(a.angular_velocity) + length(b.angular_velocity));
        expect_close(laws::restitution, -e * u, normal_velocity_at(a, b, p, n), rounding_tolerance(scale, 4096), "m/s",
                     situation + " (u' after applying J n; u = " + format(u) + " m/s)");
    }
}

TEST_CASE("apply_impulse: dv = J / m and dw = I^-1 (r x J) on both bodies, random", "[angular-impulse][step:4:apply-impulse][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    for (int i = 0; i < 40; ++i) {
        const Vector3 a_centre = random.vector(3.0);
        RigidBody a = random_box(random, a_centre);
        const Vector3 b_centre = random.vector(3.0);
        RigidBody b = random_box(random, b_centre);
        const RigidBody a0 = a, b0 = b;
        const Vector3 p = random.vector(3.0);
        const Vector3 impulse = random.vector(5.0);
        const std::string situation = pair_text(a0, b0) + "\nimpulse " + format(impulse) + " N s at " + format(p) + " m";
        angular_impulse::apply_impulse(a, b, p, impulse);
        const Vector3 dw1 = inverse(a0.inertia_world()) * cross(p - a0.position, impulse);
        const Vector3 dw2 = -(inverse(b0.inertia_world()) * cross(p - b0.position, impulse));
        const double tol1 = rounding_tolerance(length(a0.angular_velocity) + 10.0 * length(dw1), 1024);
        const double tol2 = rounding_tolerance(length(b0.angular_velocity) + 10.0 * length(dw2), 1024);
        expect_close(laws::impulse_response, a0.velocity + a0.inverse_mass * impulse, a.velocity,
                     rounding_tolerance(length(a0.velocity) + a0.inverse_mass * length(impulse), 64), "m/s", situation + " (v1)");
        expect_close(laws::impulse_response, b0.velocity - b0.inverse_mass * impulse, b.velocity,
                     rounding_tolerance(length(b0.velocity) + b0.inverse_mass * length(impulse), 64), "m/s", situation + " (v2)");
        expect_close(laws::angular_momentum, a0.angular_velocity + dw1, a.angular_velocity, tol1, "rad/s", situation + " (w1)");
        expect_close(laws::angular_momentum, b0.angular_velocity + dw2, b.angular_velocity, tol2, "rad/s", situation + " (w2)");
    }
}

TEST_CASE("an immovable or kinematic body on either side is neither moved nor turned", "[angular-impulse][step:4:apply-impulse][points:2]") {
    RigidBody platform = make_immovable_sphere(1.0, {0, 0, -1});
    platform.velocity = {0.5, 0, 0};
    platform.angular_velocity = {0, 0, 0.3};
    RigidBody box = make_box(2.0, {0.5, 0.5, 0.5}, {0.2, 0.1, 0.5}, from_axis_angle({1, 1, 0}, 0.3), {0, 0, -1});
    const Vector3 p{0.5, 0.4, 0};
    const Vector3 impulse{0, 0, 3};
    angular_impulse::apply_impulse(box, platform, p, impulse);
    expect_close(laws::immovable, Vector3{0.5, 0, 0}, platform.velocity, 0.0, "m/s", "a kinematic platform as body 2 (velocity after)");
    expect_close(laws::immovable, Vector3{0, 0, 0.3}, platform.angular_velocity, 0.0, "rad/s", "a kinematic platform as body 2 (spin after)");
    expect_close(laws::impulse_response, Vector3{0, 0, 0.5}, box.velocity, rounding_tolerance(1.0), "m/s", "a box (2 kg) pushed up by 3 N s");
    angular_impulse::apply_impulse(platform, box, p, -impulse);
    expect_close(laws::immovable, Vector3{0.5, 0, 0}, platform.velocity, 0.0, "m/s", "a kinematic platform as body 1 (velocity after)");
    expect_close(laws::immovable, Vector3{0, 0, 0.3}, platform.angular_velocity, 0.0, "rad/s", "a kinematic platform as body 1 (spin after)");
}

TEST_CASE("random single-point contacts: restitution, momentum, angular momentum, energy", "[angular-impulse][step:5:one-point][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    int resolved = 0;
    for (int i = 0; i < 60; ++i) {
        const Vector3 a_centre = random.vector(1.0);
        RigidBody a = random_box(random, a_centre);
        const Vector3 b_centre = random.vector(1.0);
        RigidBody b = random_box(random, b_centre);
        a.restitution = random.uniform(0.0, 1.0);
        b.restitution = i % 3 == 0 ? 1.0 : random.uniform(0.0, 1.0);
        const double e = std::min(a.restitution, b.restitution);
        const Vector3 n = random.direction();
        const Vector3 p = random.vector(1.0);
        const double u = normal_velocity_at(a, b, p, n);
        const std::string situation = pair_text(a, b) + "\npoint " + format(p) + " m, n = " + format(n) + ", e = " + format(e) +
                                      ", u = " + format(u) + " m/s";
        const RigidBody a0 = a, b0 = b;
        const Vector3 p0 = momentum(a, b), l0 = angular_momentum(a, b);
        const double k0 = kinetic(a) + kinetic(b);
        angular_impulse::resolve(a, b, contact_at(n, p));
        if (u >= 0.0) {
            expect_close(laws::separating, a0.velocity, a.velocity, 0.0, "m/s", situation + " (receding: body 1 velocity)");
            expect_close(laws::separating, b0.angular_velocity, b.angular_velocity, 0.0, "rad/s", situation + " (receding: body 2 spin)");
            continue;
        }
        ++resolved;
        const double scale = 3.0 * (length(a.velocity) + length(b.velocity) + length(a.angular_velocity) + length(b.angular_velocity) +
                                    length(a0.velocity) + length(b0.velocity));
        expect_close(laws::restitution, -e * u, normal_velocity_at(testing::judged(a0, a), testing::judged(b0, b), p, n), rounding_tolerance(scale, 4096),
                     "m/s", situation);
        const double p_scale = a0.mass() * (length(a.velocity) + length(a0.velocity)) + b0.mass() * (length(b.velocity) + length(b0.velocity));
        expect_close(laws::momentum, p0, momentum(testing::judged(a0, a), testing::judged(b0, b)), rounding_tolerance(p_scale, 256), "kg m/s", situation);
        expect_close(laws::angular_momentum, l0, angular_momentum(testing::judged(a0, a), testing::judged(b0, b)), rounding_tolerance(10.0 * p_scale + length(l0), 4096), "kg m^2/s",
                     situation + " (about the origin)");
        const double k1 = kinetic(testing::judged(a0, a)) + kinetic(testing::judged(b0, b));
        if (e == 1.0)
            expect_close(laws::energy, k0, k1, rounding_tolerance(k0, 4096), "J", situation + " (e = 1)");
        else
            expect_at_least(laws::energy, k1, k0, rounding_tolerance(k0, 4096), "J", situation + " (energy before, at least the energy after)");
    }
    CHECK(resolved > 10);
}

TEST_CASE("a rod dropped onto a moving platform, and a central hit equal to chapter 3's", "[angular-impulse][step:5:one-point][points:2]") {
    const double mass = 1.5, length = 2.0, theta = 60.0 * degrees, speed = 4.0, e = 0.25;
    RigidBody rod = thin_rod(mass, length, theta, {0, 0, 1}, {0, 0, -speed});
    rod.restitution = e;
    RigidBody platform = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    platform.velocity = {0, 0, 1};  // rising at 1 m/s: the rod meets it at 5 m/s
    const Vector3 end = rod_lower_end(rod, length);
    angular_impulse::resolve(rod, platform, contact_at({0, 0, 1}, end));
    const double c = std::cos(theta);
    const double j = (1.0 + e) * mass * (speed + 1.0) / (1.0 + 3.0 * c * c);
    const std::string situation = "rod m = 1.5 kg, L = 2 m, theta = 60 deg, falling at 4 m/s onto a platform rising at 1 m/s, e = 0.25";
    expect_close(laws::restitution, e * (speed + 1.0), normal_velocity_at(rod, platform, end, {0, 0, 1}), 1e-9 * 5.0, "m/s",
                 situation + " (the end's velocity relative to the platform after)");
    expect_close(laws::rod, 6.0 * j * c / (mass * length), rod.angular_velocity.y, 1e-9 * 10.0, "rad/s", situation);

    RigidBody b1 = make_sphere(2.0, 0.5, {0, 0, 0}, {3, 0, 0});
    RigidBody b2 = make_sphere(1.0, 0.5, {1, 0, 0}, {0, 0, 0});
    b1.restitution = 0.5;
    angular_impulse::resolve(b1, b2, contact_at({-1, 0, 0}, Vector3{0.5, 0, 0}));
    // Chapter 3's worked example: 2 kg at 3 m/s into 1 kg at rest, e = 0.5: 1.5 m/s and 3 m/s.
    expect_close(laws::central, Vector3{1.5, 0, 0}, b1.velocity, rounding_tolerance(3.0), "m/s", "2 kg at 3 m/s into 1 kg at rest, e = 0.5 (body 1)");
    expect_close(laws::central, Vector3{3, 0, 0}, b2.velocity, rounding_tolerance(3.0), "m/s", "2 kg at 3 m/s into 1 kg at rest, e = 0.5 (body 2)");
    expect_close(laws::central, Vector3{}, b1.angular_velocity, 0.0, "rad/s", "2 kg at 3 m/s into 1 kg at rest, e = 0.5 (body 1 spin)");
}

TEST_CASE("random boxes landing flat, turned about the vertical: straight bounce", "[angular-impulse][step:6:several-points][points:3]") {
    testing::SeededRandom random(testing::run_seed());
    RigidBody floor = ground();
    for (int i = 0; i < 20; ++i) {
        const Vector3 half{random.uniform(0.05, 2.0), random.uniform(0.05, 2.0), random.uniform(0.05, 2.0)};
        const double mass = random.log_uniform(-1, 2);
        const double speed = random.uniform(0.5, 10.0);
        const double e = random.uniform(0.0, 1.0);
        FlatLanding landing(mass, half, random.uniform(0.0, 2.0 * std::numbers::pi), speed, e);
        const std::string situation = describe_body(landing.box) + ", half extents " + format(half) + " m, e = " + format(e) +
                                      ", four corners on the ground";
        angular_impulse::resolve(landing.box, floor, landing.contact);
        expect_close(laws::flat, Vector3{0, 0, e * speed}, landing.box.velocity, 1e-9 * speed, "m/s", situation + " (velocity after)");
        expect_close(laws::flat, Vector3{}, landing.box.angular_velocity, 1e-9, "rad/s", situation + " (angular velocity after)");
    }
}

TEST_CASE("a plank 4 m by 10 cm landing flat: its corner points nearly coincide in pairs", "[angular-impulse][step:6:several-points][points:2]") {
    RigidBody floor = ground();
    FlatLanding landing(3.0, {2.0, 0.05, 1.0}, 0.3, 4.0, 0.5);
    const std::string situation = describe_body(landing.box) + ", half extents (2, 0.05, 1) m, e = 0.5, four corners on the ground";
    angular_impulse::resolve(landing.box, floor, landing.contact);
    expect_close(laws::flat, Vector3{0, 0, 2}, landing.box.velocity, 1e-9, "m/s", situation + " (velocity after)");
    expect_close(laws::flat, Vector3{}, landing.box.angular_velocity, 1e-9, "rad/s", situation + " (angular velocity after)");
}

TEST_CASE("a box landing flat on a resting box: every point at -e u, momentum kept, energy not gained",
          "[angular-impulse][step:6:several-points][points:3]") {
    const Vector3 half{0.5, 0.4, 0.3};
    // Both turned about the vertical, so that their world inertia tensors are not diagonal.
    const Quaternion top_turn = from_axis_angle({0, 0, 1}, 20.0 * degrees);
    RigidBody top = make_box(2.0, half, {0.1, 0.05, 0.3}, top_turn, {0.2, 0, -3});
    top.angular_velocity = {0, 0, 1.5};  // spinning about the vertical: tangential only
    top.restitution = 0.6;
    RigidBody bottom = make_box(5.0, {1.5, 0.8, 0.5}, {0, 0, -0.5}, from_axis_angle({0, 0, 1}, 30.0 * degrees));
    const Vector3 n{0, 0, 1};
    Contact contact;
    contact.normal = n;
    for (const Vector3 corner : {Vector3{-1, -1, -1}, Vector3{1, -1, -1}, Vector3{1, 1, -1}, Vector3{-1, 1, -1}})
        contact.add_point(top.position + rotate(top_turn, Vector3{corner.x * half.x, corner.y * half.y, corner.z * half.z}), 1e-3);
    const std::string situation = pair_text(top, bottom) + "\nfour corners, e = 0.6";
    const Vector3 p0 = momentum(top, bottom), l0 = angular_momentum(top, bottom);
    const double k0 = kinetic(top) + kinetic(bottom);
    std::array<double, 4> u{};
    for (std::size_t i = 0; i < 4; ++i) u[i] = normal_velocity_at(top, bottom, contact.points[i].position, n);
    const RigidBody top_sent = top;
    const RigidBody bottom_sent = bottom;
    angular_impulse::resolve(top, bottom, contact);
    for (std::size_t i = 0; i < 4; ++i)
        expect_close(laws::every_point, -0.6 * u[i],
                     normal_velocity_at(testing::judged(top_sent, top), testing::judged(bottom_sent, bottom), contact.points[i].position, n), 1e-9, "m/s",
                     situation + " (point " + std::to_string(i + 1) + ")");
    expect_close(laws::momentum, p0, momentum(testing::judged(top_sent, top), testing::judged(bottom_sent, bottom)), rounding_tolerance(20.0, 256),
                 "kg m/s", situation);
    expect_close(laws::angular_momentum, l0, angular_momentum(testing::judged(top_sent, top), testing::judged(bottom_sent, bottom)), 1e-9, "kg m^2/s", situation + " (about the origin)");
    expect_at_least(laws::energy, kinetic(testing::judged(top_sent, top)) + kinetic(testing::judged(bottom_sent, bottom)), k0, rounding_tolerance(k0, 1024), "J", situation);
}

TEST_CASE("boxes landing on an edge at many tilts: the closed form", "[angular-impulse][step:6:several-points][points:2]") {
    testing::SeededRandom random(testing::run_seed());
    RigidBody floor = ground();
    for (int i = 0; i < 20; ++i) {
        const Vector3 half{random.uniform(0.1, 1.0), random.uniform(0.1, 1.0), random.uniform(0.1, 1.0)};
        const double mass = random.log_uniform(-1, 1);
        const double e = random.uniform(0.0, 1.0);
        const double speed = random.uniform(0.5, 5.0);
        const double tilt = random.uniform(5.0, 85.0) * degrees;
        const Quaternion turn = from_axis_angle({1, 0, 0}, tilt);
        const Vector3 r = rotate(turn, Vector3{0, -half.y, -half.z});
        RigidBody box = make_box(mass, half, Vector3{0, 0, -r.z}, turn, {0, 0, -speed});
        box.restitution = e;
        const Vector3 middle = box.position + r;
        const Contact contact = contact_at({0, 0, 1}, middle + Vector3{half.x, 0, 0}, middle - Vector3{half.x, 0, 0});
        const double moment = mass / 3.0 * (half.y * half.y + half.z * half.z);
        const double total = (1.0 + e) * speed / (1.0 / mass + r.y * r.y / moment);
        const std::string situation = "box m = " + format(mass) + " kg, half extents " + format(half) + " m, tilted " +
                                      format(tilt / degrees) + " deg about x, falling at " + format(speed) + " m/s onto its edge, e = " + format(e);
        angular_impulse::resolve(box, floor, contact);
        expect_close(laws::edge, Vector3{0, 0, -speed + total / mass}, box.velocity, 1e-9 * speed, "m/s", situation + " (velocity)");
        expect_close(laws::edge, Vector3{r.y * total / moment, 0, 0}, box.angular_velocity, 1e-9 * (1.0 + speed / half.z), "rad/s",
                     situation + " (angular velocity)");
    }
}
