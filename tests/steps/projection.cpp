// Public step tests for chapter 2, the projection method.
// Tags: [projection] chapter, [step:N:name] the step a test grades, [points:P] its weight.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>

#include "feedback.hpp"
#include "sent_values.hpp"
#include "projection.hpp"
#include "projection_laws.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
namespace laws = workbook::projection_laws;
using workbook::testing::describe;
using workbook::testing::expect_close;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

constexpr PositionCorrection whole_depth{1.0, 0.0};

RigidBody ball(double mass, Vector3 position, Vector3 velocity = {}) { return make_sphere(mass, 0.5, position, velocity); }

/// The contact of two overlapping balls, normal from body 2 to body 1, depth r1 + r2 - distance.
Contact overlap(const RigidBody& body1, const RigidBody& body2) {
    Contact c;
    const Vector3 apart = body1.position - body2.position;
    c.normal = normalized(apart);
    c.add_point(body2.position + c.normal * body2.shape.radius,
                body1.shape.radius + body2.shape.radius - length(apart));
    return c;
}

std::string body_text(const RigidBody& body) { return describe(body) + ", x = " + format(body.position) + " m"; }

std::string pair_text(const RigidBody& a, const RigidBody& b, const Contact& c) {
    return "body 1: " + body_text(a) + "; body 2: " + body_text(b) + "; normal " + format(c.normal) + ", depth " +
           format(c.penetration) + " m";
}

/// A few ulps of the positions and depth involved: how exact a moved position can be.
double position_tolerance(const RigidBody& a, const RigidBody& b, double depth) {
    return rounding_tolerance(length(a.position) + length(b.position) + depth);
}

}  // namespace

TEST_CASE("two equal balls overlapping by 2 cm each move 1 cm apart", "[projection][step:1:split-by-inverse-mass][points:2]") {
    RigidBody ball1 = ball(1.0, {0.49, 0, 0});
    RigidBody ball2 = ball(1.0, {-0.49, 0, 0});
    const Contact contact = overlap(ball1, ball2);
    const std::string situation = pair_text(ball1, ball2, contact);
    const double tolerance = position_tolerance(ball1, ball2, contact.penetration);
    projection::correct(ball1, ball2, contact, whole_depth);
    expect_close(laws::split, Vector3{0.5, 0, 0}, ball1.position, tolerance, "m", situation + " (body 1's position after)");
    expect_close(laws::split, Vector3{-0.5, 0, 0}, ball2.position, tolerance, "m", situation + " (body 2's position after)");
}

TEST_CASE("a 3 kg and a 1 kg ball: the light one moves three quarters of the depth, the centre of mass stays",
          "[projection][step:1:split-by-inverse-mass][points:2]") {
    // A normal off every axis, (0.6, 0.8, 0), and a depth of 4 cm.
    RigidBody heavy = ball(3.0, {0.576, 0.768, 0});
    RigidBody light = ball(1.0, {0, 0, 0});
    const Contact contact = overlap(heavy, light);
    const std::string situation = pair_text(heavy, light, contact);
    const RigidBody heavy_before = heavy;
    const RigidBody light_before = light;
    const double tolerance = position_tolerance(heavy, light, contact.penetration);
    projection::correct(heavy, light, contact, whole_depth);
    expect_close(laws::split, Vector3{0.006, 0.008, 0}, heavy.position - heavy_before.position, tolerance, "m",
                 situation + " (body 1's displacement: a quarter of 4 cm along n)");
    expect_close(laws::split, Vector3{-0.018, -0.024, 0}, light.position - light_before.position, tolerance, "m",
                 situation + " (body 2's displacement: three quarters of 4 cm along -n)");
    const Vector3 mass_weighted = 3.0 * (heavy.position - heavy_before.position) + 1.0 * (light.position - light_before.position);
    expect_close(laws::centre_of_mass, Vector3{}, mass_weighted, 4.0 * tolerance, "kg m",
                 situation + " (m1 dx1 + m2 dx2)");
}

TEST_CASE("a contact with several points is pushed out by its deepest one", "[projection][step:1:split-by-inverse-mass][points:2]") {
    // A box face resting on another at four corners, sunk 1, 3, 2 and 0 cm (normal +y).
    RigidBody top = ball(2.0, {0, 1, 0});
    RigidBody bottom = ball(2.0, {0, 0, 0});
    Contact contact;
    contact.normal = {0, 1, 0};
    contact.add_point({0.5, 0.5, 0.5}, 0.01);
    contact.add_point({-0.5, 0.5, 0.5}, 0.03);
    contact.add_point({-0.5, 0.5, -0.5}, 0.02);
    contact.add_point({0.5, 0.5, -0.5}, 0.0);
    const std::string situation = pair_text(top, bottom, contact) + " (points 1, 3, 2 and 0 cm deep)";
    const double tolerance = position_tolerance(top, bottom, contact.penetration);
    projection::correct(top, bottom, contact, whole_depth);
    expect_close(laws::split, 1.03, top.position.y - bottom.position.y, tolerance, "m",
                 situation + " (the distance between the centres after)");
    expect_close(laws::centre_of_mass, 0.5, (top.position.y + bottom.position.y) / 2.0, tolerance, "m",
                 situation + " (the height of the centre of mass after)");
}

TEST_CASE("a ball sunk 5 cm into the immovable ground is lifted 5 cm, the ground stays", "[projection][step:2:immovable-bodies][points:2]") {
    RigidBody ball1 = ball(2.0, {0.3, 0.45, 0});
    RigidBody ground = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    Contact contact;
    contact.normal = {0, 1, 0};
    contact.add_point({0.3, 0, 0}, 0.05);
    const std::string situation = pair_text(ball1, ground, contact);
    projection::correct(ball1, ground, contact, whole_depth);
    expect_close(laws::immovable, Vector3{}, ground.position, 0.0, "m", situation + " (the ground's position after)");
    expect_close(laws::immovable, Vector3{0.3, 0.5, 0}, ball1.position, rounding_tolerance(0.5), "m",
                 situation + " (the ball's position after)");
}

TEST_CASE("an immovable body on either side, and two immovable bodies", "[projection][step:2:immovable-bodies][points:2]") {
    RigidBody wall = make_immovable_sphere(0.5, {0, 0, 0});
    RigidBody ball2 = ball(5.0, {0, -0.9, 0});
    Contact contact = overlap(wall, ball2);
    std::string situation = pair_text(wall, ball2, contact);
    projection::correct(wall, ball2, contact, whole_depth);
    expect_close(laws::immovable, Vector3{}, wall.position, 0.0, "m", situation + " (the wall, body 1, after)");
    expect_close(laws::immovable, Vector3{0, -1.0, 0}, ball2.position, rounding_tolerance(1.0), "m",
                 situation + " (the ball, body 2, after)");

    RigidBody wall1 = make_immovable_sphere(0.5, {0, 0, 0});
    RigidBody wall2 = make_immovable_sphere(0.5, {0.8, 0, 0});
    contact = overlap(wall1, wall2);
    situation = pair_text(wall1, wall2, contact);
    projection::correct(wall1, wall2, contact, whole_depth);
    expect_close(laws::immovable, Vector3{0, 0, 0}, wall1.position, 0.0, "m", situation + " (immovable body 1 after)");
    expect_close(laws::immovable, Vector3{0.8, 0, 0}, wall2.position, 0.0, "m", situation + " (immovable body 2 after)");
}

TEST_CASE("two approaching balls are pushed apart and keep their velocities", "[projection][step:3:positions-only][points:2]") {
    RigidBody ball1 = ball(2.0, {-0.48, 0, 0}, {3, 1, 0});
    RigidBody ball2 = ball(1.0, {0.48, 0, 0}, {-2, 0, 0.5});
    // Body 1 is the right-hand ball, so the normal is +x.
    const Contact contact = overlap(ball2, ball1);
    const std::string situation = pair_text(ball2, ball1, contact);
    const RigidBody before1 = ball1;
    const RigidBody before2 = ball2;
    projection::correct(ball2, ball1, contact, whole_depth);
    expect_close(laws::positions_only, before1.velocity, ball1.velocity, 0.0, "m/s", situation + " (body 2's velocity after)");
    expect_close(laws::positions_only, before2.velocity, ball2.velocity, 0.0, "m/s", situation + " (body 1's velocity after)");
    workbook::testing::expect_at_least(laws::still_pushed, 1.0, ball2.position.x - ball1.position.x, rounding_tolerance(1.0),
                                       "m", situation + " (the distance between the centres after)");
}

TEST_CASE("a spinning ball keeps its spin, momentum and kinetic energy", "[projection][step:3:positions-only][points:2]") {
    RigidBody spinner = ball(4.0, {0, 0.47, 0}, {1, -2, 0});
    spinner.angular_velocity = {0, 0, 10};
    RigidBody other = ball(4.0, {0, -0.47, 0}, {0, 2, 0});
    other.angular_velocity = {3, 0, 0};
    const Contact contact = overlap(spinner, other);
    const std::string situation = pair_text(spinner, other, contact);
    const RigidBody before1 = spinner;
    const RigidBody before2 = other;
    const double energy_before = kinetic_energy(spinner) + kinetic_energy(other);
    projection::correct(spinner, other, contact, whole_depth);
    expect_close(laws::positions_only, before1.angular_velocity, spinner.angular_velocity, 0.0, "rad/s",
                 situation + " (body 1's angular velocity after)");
    expect_close(laws::positions_only, before2.angular_velocity, other.angular_velocity, 0.0, "rad/s",
                 situation + " (body 2's angular velocity after)");
    expect_close(laws::positions_only, energy_before, kinetic_energy(testing::judged(before1, spinner)) + kinetic_energy(testing::judged(before2, other)), 0.0, "J",
                 situation + " (kinetic energy after)");
    workbook::testing::expect_at_least(laws::still_pushed, 1.0, spinner.position.y - other.position.y, rounding_tolerance(1.0),
                                       "m", situation + " (the distance between the centres after)");
}

TEST_CASE("a fifth of the depth beyond a 1 cm slop, and nothing within it", "[projection][step:4:fraction-and-slop][points:2]") {
    const PositionCorrection knobs{0.2, 0.01};
    expect_close(laws::knobs, 0.008, projection::depth_to_remove(0.05, knobs), rounding_tolerance(0.05), "m",
                 "depth_to_remove(0.05 m) with fraction 0.2 and slop 0.01 m");
    expect_close(laws::knobs, 0.0, projection::depth_to_remove(0.01, knobs), 0.0, "m",
                 "depth_to_remove(0.01 m), exactly the slop, with fraction 0.2");
    expect_close(laws::knobs, 0.0, projection::depth_to_remove(0.004, knobs), 0.0, "m",
                 "depth_to_remove(0.004 m), within the slop, with fraction 0.2");
}

TEST_CASE("two equal balls 5 cm deep with fraction 0.2 and slop 1 cm move 4 mm each", "[projection][step:4:fraction-and-slop][points:2]") {
    const PositionCorrection knobs{0.2, 0.01};
    RigidBody ball1 = ball(1.0, {0.475, 0, 0});
    RigidBody ball2 = ball(1.0, {-0.475, 0, 0});
    const Contact contact = overlap(ball1, ball2);
    const std::string situation = pair_text(ball1, ball2, contact) + ", fraction 0.2, slop 0.01 m";
    const double tolerance = position_tolerance(ball1, ball2, contact.penetration);
    projection::correct(ball1, ball2, contact, knobs);
    expect_close(laws::knobs, 0.479, ball1.position.x, tolerance, "m", situation + " (body 1's x after)");
    expect_close(laws::knobs, -0.479, ball2.position.x, tolerance, "m", situation + " (body 2's x after)");

    RigidBody shallow1 = ball(1.0, {0.498, 0, 0});
    RigidBody shallow2 = ball(1.0, {-0.498, 0, 0});
    const Contact within = overlap(shallow1, shallow2);
    // The case as it was before the correction: the positions after it are what is checked.
    const std::string shallow = pair_text(shallow1, shallow2, within) + ", fraction 0.2, slop 0.01 m: within the slop";
    projection::correct(shallow1, shallow2, within, knobs);
    expect_close(laws::knobs, 0.498, shallow1.position.x, 0.0, "m", shallow + " (body 1's x after, unmoved)");
    expect_close(laws::knobs, -0.498, shallow2.position.x, 0.0, "m", shallow + " (body 2's x after, unmoved)");
}

TEST_CASE("repeated passes leave s + (d0 - s)(1 - beta)^k of the depth", "[projection][step:4:fraction-and-slop][points:2]") {
    // Half the depth beyond a 1 mm slop per pass, from 4.1 cm: after five passes 1 mm + 4 cm / 32 remain.
    const PositionCorrection knobs{0.5, 0.001};
    RigidBody ball1 = ball(1.0, {0.4795, 0, 0});
    RigidBody ball2 = ball(1.0, {-0.4795, 0, 0});
    const std::string situation = "two 1 kg balls of radius 0.5 m, 4.1 cm deep, fraction 0.5, slop 0.001 m";
    for (int pass = 0; pass < 5; ++pass) projection::correct(ball1, ball2, overlap(ball1, ball2), knobs);
    const double depth = 1.0 - (ball1.position.x - ball2.position.x);
    expect_close(laws::decay, 0.001 + 0.04 / 32.0, depth, rounding_tolerance(1.0, 64.0), "m",
                 situation + " (the depth after five passes, each measured afresh)");
}
