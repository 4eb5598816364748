// Public step tests for chapter 5, resting contact.
// Tags: [resting-contact] chapter, [step:N:name] the step a test grades, [points:P] its weight.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "feedback.hpp"
#include "resting-contact.hpp"
#include "resting_contact_laws.hpp"
#include "resting_contact_column.hpp"
#include "workbook/world.hpp"

using namespace workbook;
namespace laws = workbook::resting_contact_laws;
using workbook::testing::expect_at_least;
using workbook::testing::expect_close;
using workbook::testing::format;
using workbook::testing::rounding_tolerance;

namespace {

RigidBody ground() { return make_immovable_plane({0, 0, 1}, {0, 0, 0}); }

Contact contact_at(const Vector3& normal, const Vector3& point, double depth, std::uint32_t body1 = 0,
                   std::uint32_t body2 = 1) {
    Contact c;
    c.body1 = body1;
    c.body2 = body2;
    c.normal = normal;
    c.add_point(point, depth);
    return c;
}

double normal_velocity(const RigidBody& b1, const RigidBody& b2, const Vector3& p, const Vector3& n) {
    auto at = [&](const RigidBody& b) { return b.velocity + cross(b.angular_velocity, p - b.position); };
    return dot(at(b1) - at(b2), n);
}

}  // namespace

TEST_CASE("two balls of 1 and 3 kg touching: the effective mass is the reduced mass, 0.75 kg",
          "[resting-contact][step:1:normal-mass][points:2]") {
    const RigidBody a = make_sphere(1.0, 0.5, {0, 0, 1});
    const RigidBody b = make_sphere(3.0, 0.5, {0, 0, 0});
    expect_close(laws::effective_mass, 0.75, resting_contact::normal_mass(a, b, {0, 0, 0.5}, {0, 0, 1}),
                 rounding_tolerance(0.75), "kg", "balls at (0, 0, 1) and (0, 0, 0), point (0, 0, 0.5), normal +z");
}

TEST_CASE("a 2 kg cube standing on one corner of its bottom face: m/4 = 0.5 kg, and 0 between two immovable bodies",
          "[resting-contact][step:1:normal-mass][points:2]") {
    const double h = 0.1;
    const RigidBody cube = make_box(2.0, {h, h, h}, {0, 0, h});
    // r = (h, h, -h): the angular term adds 3/m to 1/m.
    expect_close(laws::effective_mass, 0.5, resting_contact::normal_mass(cube, ground(), {h, h, 0}, {0, 0, 1}),
                 rounding_tolerance(0.5, 32), "kg", "a 2 kg cube of side 0.2 m, point at its corner (0.1, 0.1, 0)");
    expect_close(laws::effective_mass, 0.0,
                 resting_contact::normal_mass(make_immovable_sphere(1.0, {0, 0, 2}), ground(), {0, 0, 1}, {0, 0, 1}), 0.0,
                 "kg", "an immovable ball on the immovable ground");
}

TEST_CASE("accumulate keeps the running sum non-negative and returns its change",
          "[resting-contact][step:2:accumulate][points:3]") {
    struct Case {
        double before, increment, after;
    };
    for (const Case c : {Case{0.0, 1.5, 1.5}, Case{2.0, -0.5, 1.5}, Case{2.0, -3.0, 0.0}, Case{0.0, -1.0, 0.0}}) {
        double sum = c.before;
        const double applied = resting_contact::accumulate(sum, c.increment);
        const std::string situation = "accumulated " + format(c.before) + " kg m/s, increment " + format(c.increment);
        expect_close(laws::accumulated, c.after, sum, rounding_tolerance(2.0), "kg m/s", situation + " (the new sum)");
        expect_close(laws::accumulated, c.after - c.before, applied, rounding_tolerance(2.0), "kg m/s",
                     situation + " (the impulse to apply)");
    }
}

TEST_CASE("a 1 kg ball 1 cm deep in the ground falling at 2 m/s, e = 0.5: bounce 1 m/s, bias 0.4 m/s",
          "[resting-contact][step:3:prepare][points:3]") {
    RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.09}, {0, 0, -2});
    ball.restitution = 0.5;
    RigidBody floor = ground();
    floor.restitution = 0.5;
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0}, 0.01);
    ContactImpulses impulses;
    impulses.points[0].normal = 3.0;  // set by the world: must stay
    impulses.points[0].pseudo = 7.0;  // left from last step: must be reset
    const ContactSolverSettings settings;
    resting_contact::prepare(ball, floor, contact, impulses, settings, {0.5, 0.002}, 0.01);
    const std::string situation = "ball 1 kg at 2 m/s down, e = 0.5, depth 0.01 m, fraction 0.5, slop 0.002 m, dt 0.01 s";
    expect_close(laws::effective_mass, 1.0, impulses.points[0].mass, rounding_tolerance(1.0), "kg", situation);
    expect_close(laws::bounce, 1.0, impulses.points[0].bounce, rounding_tolerance(1.0), "m/s", situation);
    expect_close(laws::bias, 0.4, impulses.points[0].bias, rounding_tolerance(0.4, 64), "m/s", situation);
    expect_close(laws::bias, 0.0, impulses.points[0].pseudo, 0.0, "kg m/s", situation + " (pseudo reset)");
    expect_close(laws::bias, 3.0, impulses.points[0].normal, 0.0, "kg m/s", situation + " (normal left alone)");
}

TEST_CASE("a ball resting on the ground at gravity's speed of one step gets no bounce",
          "[resting-contact][step:3:prepare][points:2]") {
    RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1}, {0, 0, -9.81 / 60});
    ball.restitution = 1.0;
    RigidBody floor = ground();
    floor.restitution = 1.0;
    ContactImpulses impulses;
    impulses.points[0].bounce = impulses.points[0].bias = 7.0;  // left from another contact: prepare overwrites them
    resting_contact::prepare(ball, floor, contact_at({0, 0, 1}, {0, 0, 0}, 0.0), impulses, ContactSolverSettings{},
                             {0.5, 0.002}, 1.0 / 60);
    expect_close(laws::bounce, 0.0, impulses.points[0].bounce, 0.0, "m/s",
                 "e = 1, approaching at 0.1635 m/s, below the threshold of 0.5 m/s");
    expect_close(laws::bias, 0.0, impulses.points[0].bias, 0.0, "m/s", "depth 0, below the slop");
}

TEST_CASE("warm starting a box on a box with 2 kg m/s at a corner of the face they share",
          "[resting-contact][step:4:warm-start][points:3]") {
    RigidBody top = make_box(2.0, {0.5, 0.5, 0.5}, {0, 0, 1});
    RigidBody bottom = make_box(4.0, {0.5, 0.5, 0.5}, {0.3, 0, 0});  // off to the side: a lever arm of its own
    const Vector3 corner{0.5, 0.5, 0.5};
    const Contact contact = contact_at({0, 0, 1}, corner, 0.0);
    ContactImpulses impulses;
    impulses.points[0].normal = 2.0;
    resting_contact::warm_start(top, bottom, contact, impulses);
    const Vector3 j{0, 0, 2};
    const std::string situation = "cubes of 2 and 4 kg, 1 m a side, the upper at (0, 0, 1), the lower at (0.3, 0, 0), J = " + format(j) + " at the corner " + format(corner);
    expect_close(laws::warm, j / 2.0, top.velocity, rounding_tolerance(1.0), "m/s", situation + " (body 1)");
    expect_close(laws::warm, -j / 4.0, bottom.velocity, rounding_tolerance(1.0), "m/s", situation + " (body 2)");
    // A push off the centre turns each box: w = I^-1 (r x J), each from its own centre.
    expect_close(laws::warm, top.inverse_inertia_world * cross(corner - top.position, j), top.angular_velocity,
                 rounding_tolerance(10.0), "rad/s", situation + " (body 1's spin)");
    expect_close(laws::warm, -(bottom.inverse_inertia_world * cross(corner - bottom.position, j)), bottom.angular_velocity,
                 rounding_tolerance(10.0), "rad/s", situation + " (body 2's spin)");
}

TEST_CASE("one pass stops a ball falling at 1 m/s on the ground, and takes back what a pass gave too much",
          "[resting-contact][step:5:solve-velocity][points:3]") {
    RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1}, {0, 0, -1});
    RigidBody floor = ground();
    const Contact contact = contact_at({0, 0, 1}, {0, 0, 0}, 0.0);
    ContactImpulses impulses;
    impulses.points[0].mass = 1.0;
    const double change = resting_contact::solve_velocity(ball, floor, contact, impulses);
    expect_close(laws::rest, 0.0, ball.velocity.z, rounding_tolerance(1.0), "m/s", "1 kg ball at 1 m/s down, bounce 0");
    expect_close(laws::rest, 1.0, impulses.points[0].normal, rounding_tolerance(1.0), "kg m/s", "the accumulated impulse");
    expect_close(laws::rest, 1.0, change, rounding_tolerance(1.0), "m/s", "the returned change of velocity");
    // A later pass finds the ball leaving at 0.5 m/s with 1 kg m/s accumulated: it takes 0.5 back.
    ball.velocity = {0, 0, 0.5};
    (void)resting_contact::solve_velocity(ball, floor, contact, impulses);
    expect_close(laws::rest, 0.0, ball.velocity.z, rounding_tolerance(1.0), "m/s",
                 "leaving at 0.5 m/s with 1 kg m/s accumulated: the pass takes 0.5 kg m/s back");
    expect_close(laws::rest, 0.5, impulses.points[0].normal, rounding_tolerance(1.0), "kg m/s", "the accumulated impulse");
}

TEST_CASE("a ball leaving faster than its accumulated impulse can hold keeps moving: a contact never pulls",
          "[resting-contact][step:5:solve-velocity][points:2]") {
    RigidBody ball = make_sphere(1.0, 0.1, {0, 0, 0.1}, {0, 0, 2});
    RigidBody floor = ground();
    ContactImpulses impulses;
    impulses.points[0].mass = 1.0;
    impulses.points[0].normal = 0.5;
    (void)resting_contact::solve_velocity(ball, floor, contact_at({0, 0, 1}, {0, 0, 0}, 0.0), impulses);
    expect_close(laws::no_pull, 1.5, ball.velocity.z, rounding_tolerance(2.0), "m/s",
                 "1 kg ball leaving at 2 m/s with 0.5 kg m/s accumulated");
    expect_close(laws::no_pull, 0.0, impulses.points[0].normal, 0.0, "kg m/s", "the accumulated impulse");
}

TEST_CASE("a column of five 1 kg balls on the ground: after the world's solve each contact carries the weight above it",
          "[resting-contact][step:5:solve-velocity][points:4]") {
    const int n = 5;
    std::vector<RigidBody> bodies;
    for (int i = 0; i < n; ++i) bodies.push_back(make_sphere(1.0, 0.05, {0, 0, 0.05 + 0.0995 * i}));
    bodies.push_back(ground());
    WorldSettings settings{1.0 / 60, {0, 0, -9.81}};
    settings.contact_solver.velocity_iterations = 500;
    // solve_velocity alone: the rest of the solve is the test's (resting_contact_column.hpp).
    const ResponseModel model{"resting-contact", nullptr, nullptr, &resting_contact_column::velocity_pass_alone};
    World world(std::move(bodies), settings, model);
    world.step();
    const double g_dt = 9.81 / 60;
    std::vector<double> carried;
    for (const ContactImpulses& c : world.contact_solver().impulses()) carried.push_back(c.points[0].normal);
    std::sort(carried.begin(), carried.end());
    const double tolerance = 1e-7;  // the solver stops once no pass changes a velocity by more than 1e-9 m/s
    for (std::size_t k = 0; k < carried.size(); ++k)
        expect_close(laws::stack, static_cast<double>(k + 1) * g_dt, carried[k], tolerance, "kg m/s",
                     "column of 5 balls of 1 kg, dt = 1/60 s: the contact with " + std::to_string(k + 1) + " balls above it");
    for (int i = 0; i < n; ++i)
        expect_close(laws::stack, 0.0, world.bodies()[static_cast<std::size_t>(i)].velocity.z, tolerance, "m/s",
                     "ball " + std::to_string(i + 1) + " of the column after one step");
}

TEST_CASE("two balls overlapping 1 cm at rest: the position pass pushes them apart at the bias",
          "[resting-contact][step:6:solve-position][points:3]") {
    RigidBody a = make_sphere(1.0, 0.05, {0.09, 0, 0});
    RigidBody b = make_sphere(1.0, 0.05, {0, 0, 0});
    ContactImpulses impulses;
    impulses.points[0].mass = 0.5;
    impulses.points[0].bias = 0.6;
    impulses.points[0].normal = 4.0;
    const Vector3 n{1, 0, 0};
    (void)resting_contact::solve_position(a, b, contact_at(n, {0.045, 0, 0}, 0.01), impulses);
    expect_close(laws::pseudo, 0.6, normal_velocity(a, b, {0.045, 0, 0}, n), rounding_tolerance(0.6), "m/s",
                 "balls of 1 kg at pseudo-velocity 0, bias 0.6 m/s");
    expect_close(laws::pseudo, 0.3, impulses.points[0].pseudo, rounding_tolerance(0.3), "kg m/s", "the accumulated pseudo-impulse");
    expect_close(laws::pseudo, 4.0, impulses.points[0].normal, 0.0, "kg m/s", "the velocity pass's impulse, untouched");
}
