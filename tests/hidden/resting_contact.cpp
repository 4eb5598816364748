// Hidden step tests for chapter 5, resting contact: the same steps and laws as the public
// tests, on other numbers and the cases a shortcut misses (sideways normals, both bodies
// movable, boxes, several points, a taller column).
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../steps/resting_contact_laws.hpp"
#include "../steps/resting_contact_column.hpp"
#include "feedback.hpp"
#include "resting-contact.hpp"
#include "workbook/world.hpp"

using namespace workbook;
namespace laws = workbook::resting_contact_laws;
using workbook::testing::expect_close;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

Contact contact_at(const Vector3& normal, const Vector3& point, double depth) {
    Contact c;
    c.normal = normal;
    c.add_point(point, depth);
    return c;
}

}  // namespace

TEST_CASE("hidden: a 3 kg cube against a wall at one corner: m/4 along a sideways normal",
          "[resting-contact][step:1:normal-mass][points:2]") {
    const double h = 0.25;
    const RigidBody cube = make_box(3.0, {h, h, h}, {h, 0, 0});
    const RigidBody wall = make_immovable_plane({1, 0, 0}, {0, 0, 0});
    expect_close(laws::effective_mass, 0.75, resting_contact::normal_mass(cube, wall, {0, h, -h}, {1, 0, 0}),
                 rounding_tolerance(0.75, 32), "kg", "a 3 kg cube of side 0.5 m against a wall x = 0, point at a corner");
}

TEST_CASE("hidden: a 2 kg ball on a 1 kg cube's corner: both bodies' terms",
          "[resting-contact][step:1:normal-mass][points:2]") {
    const double h = 0.1;
    const RigidBody cube = make_box(1.0, {h, h, h}, {0, 0, h});
    const RigidBody ball = make_sphere(2.0, 0.1, {h, h, 2 * h + 0.1});
    // k = 1/2 (the ball, central) + 4/1 (the cube's corner).
    expect_close(laws::effective_mass, 1.0 / 4.5, resting_contact::normal_mass(ball, cube, {h, h, 2 * h}, {0, 0, 1}),
                 rounding_tolerance(0.25, 32), "kg", "a 2 kg ball resting on a corner of a 1 kg cube of side 0.2 m");
}

TEST_CASE("hidden: accumulate takes back exactly what was given and no more",
          "[resting-contact][step:2:accumulate][points:3]") {
    struct Case {
        double before, increment, after;
    };
    for (const Case c : {Case{3.25, -3.25, 0.0}, Case{1e-3, -2e-3, 0.0}, Case{5.0, 2.5, 7.5}, Case{0.0, 0.0, 0.0}}) {
        double sum = c.before;
        const double applied = resting_contact::accumulate(sum, c.increment);
        const std::string situation = "accumulated " + format(c.before) + " kg m/s, increment " + format(c.increment);
        expect_close(laws::accumulated, c.after, sum, rounding_tolerance(8.0), "kg m/s", situation + " (the new sum)");
        expect_close(laws::accumulated, c.after - c.before, applied, rounding_tolerance(8.0), "kg m/s",
                     situation + " (the impulse to apply)");
    }
}

TEST_CASE("hidden: two 2 kg balls meeting sideways at 3 m/s, e = 0.8, deep 3 cm: bounce, bias capped at max_push",
          "[resting-contact][step:3:prepare][points:3]") {
    // Balls of 2 kg each: an effective mass of 1 kg, so that this step's check of the mass
    // does not grade step 1's formula again.
    RigidBody a = make_sphere(2.0, 0.1, {0.17, 0, 0}, {-1, 0, 0});
    RigidBody b = make_sphere(2.0, 0.1, {0, 0, 0}, {2, 0, 0});
    a.restitution = b.restitution = 0.8;
    ContactImpulses impulses;
    const ContactSolverSettings settings;  // max_push 5 mm
    resting_contact::prepare(a, b, contact_at({1, 0, 0}, {0.085, 0, 0}, 0.03), impulses, settings, {0.5, 0.001}, 0.02);
    const std::string situation = "balls of 2 kg approaching at 3 m/s along x, e = 0.8, depth 0.03 m, dt 0.02 s";
    expect_close(laws::effective_mass, 1.0, impulses.points[0].mass, rounding_tolerance(1.0), "kg", situation);
    expect_close(laws::bounce, 2.4, impulses.points[0].bounce, rounding_tolerance(3.0), "m/s", situation);
    expect_close(laws::bias, 0.005 / 0.02, impulses.points[0].bias, rounding_tolerance(0.25, 64), "m/s",
                 situation + "; 0.5 x (0.03 - 0.001) = 0.0145 m, capped at 0.005 m");
}

TEST_CASE("hidden: a bouncy box lands tilted on a dead floor: the pair's restitution, each point's own depth",
          "[resting-contact][step:3:prepare][points:3]") {
    // e = min(0.9, 0.2) = 0.2 for the pair (workbook::combined_restitution); the box's two
    // lower corners are 4 mm and 12 mm deep.
    RigidBody box = make_box(2.0, {0.2, 0.1, 0.1}, {0, 0, 0.1}, {}, {0, 0, -3});
    box.restitution = 0.9;
    RigidBody floor = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    floor.restitution = 0.2;
    Contact contact;
    contact.normal = {0, 0, 1};
    contact.add_point({0.2, 0, 0}, 0.004);
    contact.add_point({-0.2, 0, 0}, 0.012);
    ContactImpulses impulses;
    const ContactSolverSettings settings;  // max_push 5 mm
    resting_contact::prepare(box, floor, contact, impulses, settings, {0.5, 0.002}, 0.01);
    const std::string situation = "a 2 kg box of e = 0.9 falling at 3 m/s onto a floor of e = 0.2, corners 4 and 12 mm deep, "
                                  "fraction 0.5, slop 2 mm, dt 0.01 s";
    for (std::size_t i = 0; i < 2; ++i) {
        CAPTURE(i);
        expect_close(laws::bounce, 0.6, impulses.points[i].bounce, rounding_tolerance(3.0), "m/s", situation);
    }
    expect_close(laws::bias, 0.1, impulses.points[0].bias, rounding_tolerance(0.5, 64), "m/s",
                 situation + ": 0.5 x (0.004 - 0.002) / 0.01 at the first corner");
    expect_close(laws::bias, 0.5, impulses.points[1].bias, rounding_tolerance(0.5, 64), "m/s",
                 situation + ": 0.5 x (0.012 - 0.002) / 0.01 = 0.5 m/s at the second corner");
}

TEST_CASE("hidden: warm starting a box's two corners turns it",
          "[resting-contact][step:4:warm-start][points:3]") {
    RigidBody box = make_box(2.0, {0.2, 0.1, 0.1}, {0, 0, 0.1});
    RigidBody floor = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    Contact contact;
    contact.normal = {0, 0, 1};
    contact.add_point({0.2, 0.1, 0}, 0.0);
    contact.add_point({-0.2, 0.1, 0}, 0.0);
    ContactImpulses impulses;
    impulses.points[0].normal = 1.0;
    impulses.points[1].normal = 3.0;
    resting_contact::warm_start(box, floor, contact, impulses);
    const Vector3 torque = cross(Vector3{0.2, 0.1, -0.1}, Vector3{0, 0, 1}) + cross(Vector3{-0.2, 0.1, -0.1}, Vector3{0, 0, 3});
    expect_close(laws::warm, Vector3{0, 0, 2}, box.velocity, rounding_tolerance(2.0), "m/s", "2 kg box, 1 and 3 kg m/s at two corners");
    expect_close(laws::warm, box.inverse_inertia_world * torque, box.angular_velocity, rounding_tolerance(200.0), "rad/s",
                 "the box's spin from the two corners' impulses");
}

TEST_CASE("hidden: one pass between two movable balls with a bounce target",
          "[resting-contact][step:5:solve-velocity][points:3]") {
    RigidBody a = make_sphere(1.0, 0.1, {0, 0, 0.2}, {0, 0, -2});
    RigidBody b = make_sphere(3.0, 0.1, {0, 0, 0}, {0, 0, 1});
    ContactImpulses impulses;
    impulses.points[0].mass = 0.75;
    impulses.points[0].bounce = 1.5;
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0.1}, 0.0);
    const double change = resting_contact::solve_velocity(a, b, contact, impulses);
    expect_close(laws::rest, 1.5, a.velocity.z - b.velocity.z, rounding_tolerance(4.0), "m/s",
                 "balls of 1 and 3 kg approaching at 3 m/s, bounce 1.5 m/s");
    expect_close(laws::rest, 4.5 * 0.75, impulses.points[0].normal, rounding_tolerance(4.0), "kg m/s", "the accumulated impulse");
    expect_close(laws::rest, 4.5, change, rounding_tolerance(4.0), "m/s", "the returned change");
    expect_close(laws::rest, 1.0 * -2.0 + 3.0 * 1.0, 1.0 * a.velocity.z + 3.0 * b.velocity.z, rounding_tolerance(8.0), "kg m/s",
                 "the two balls' momentum is kept");
}

TEST_CASE("hidden: a column of twelve balls, 2 kg each: each contact carries the weight above it",
          "[resting-contact][step:5:solve-velocity][points:4]") {
    const int n = 12;
    std::vector<RigidBody> bodies;
    for (int i = 0; i < n; ++i) bodies.push_back(make_sphere(2.0, 0.05, {0, 0, 0.05 + 0.0995 * i}));
    bodies.push_back(make_immovable_plane({0, 0, 1}, {0, 0, 0}));
    WorldSettings settings{1.0 / 120, {0, 0, -9.81}};
    settings.contact_solver.velocity_iterations = 2000;
    // solve_velocity alone: the rest of the solve is the test's (resting_contact_column.hpp).
    const ResponseModel model{"resting-contact", nullptr, nullptr, &resting_contact_column::velocity_pass_alone};
    World world(std::move(bodies), settings, model);
    world.step();
    std::vector<double> carried;
    for (const ContactImpulses& c : world.contact_solver().impulses()) carried.push_back(c.points[0].normal);
    std::sort(carried.begin(), carried.end());
    const double g_dt = 2.0 * 9.81 / 120;
    for (std::size_t k = 0; k < carried.size(); ++k)
        expect_close(laws::stack, static_cast<double>(k + 1) * g_dt, carried[k], 1e-6, "kg m/s",
                     "column of 12 balls of 2 kg, dt = 1/120 s: the contact with " + std::to_string(k + 1) + " balls above it");
}

TEST_CASE("hidden: the position pass between a ball and a wall", "[resting-contact][step:6:solve-position][points:3]") {
    // An earlier pass gave 0.1 kg m/s: the ball's pseudo-velocity is 0.05 m/s.
    RigidBody ball = make_sphere(2.0, 0.1, {0.095, 0, 0}, {0.05, 0, 0});
    RigidBody wall = make_immovable_plane({1, 0, 0}, {0, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].mass = 2.0;
    impulses.points[0].bias = 0.25;
    impulses.points[0].pseudo = 0.1;
    (void)resting_contact::solve_position(ball, wall, contact_at({1, 0, 0}, {0, 0, 0}, 0.005), impulses);
    expect_close(laws::pseudo, 0.25, ball.velocity.x, rounding_tolerance(0.25), "m/s",
                 "2 kg ball 5 mm into a wall, bias 0.25 m/s, 0.1 kg m/s already accumulated (pseudo-velocity 0.05 m/s)");
    expect_close(laws::pseudo, 0.5, impulses.points[0].pseudo, rounding_tolerance(0.5), "kg m/s", "the accumulated pseudo-impulse");
}
