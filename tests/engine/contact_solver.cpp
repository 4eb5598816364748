// The contact solver's loop (workbook/contact_solver.hpp) with test doubles for the chapter's
// functions: linear impulses along the normal at the centres, which are exact for balls in a
// column, so that the solver's answer is known in closed form. No chapter code is linked.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "workbook/contact_solver.hpp"
#include "workbook/probes.hpp"
#include "workbook/world.hpp"

using namespace workbook;

namespace {

double normal_velocity(const RigidBody& body1, const RigidBody& body2, const Contact& contact) {
    return dot(body1.velocity - body2.velocity, contact.normal);
}

void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings&, const PositionCorrection& knobs, double dt) {
    PointImpulse& p = impulses.points[0];
    const double k = body1.inverse_mass + body2.inverse_mass;
    p.mass = k > 0.0 ? 1.0 / k : 0.0;
    p.bounce = 0.0;
    p.bias = knobs.fraction * std::max(contact.penetration - knobs.slop, 0.0) / dt;
    p.pseudo = 0.0;
}

void push(RigidBody& body1, RigidBody& body2, const Contact& contact, double j) {
    body1.velocity += contact.normal * (j * body1.inverse_mass);
    body2.velocity -= contact.normal * (j * body2.inverse_mass);
}

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    push(body1, body2, contact, impulses.points[0].normal);
}

double pass(RigidBody& body1, RigidBody& body2, const Contact& contact, double target, double& sum, double mass) {
    const double before = sum;
    sum = std::max(before + mass * (target - normal_velocity(body1, body2, contact)), 0.0);
    push(body1, body2, contact, sum - before);
    return mass > 0.0 ? std::abs(sum - before) / mass : 0.0;
}

double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    PointImpulse& p = impulses.points[0];
    return pass(body1, body2, contact, p.bounce, p.normal, p.mass);
}

double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    PointImpulse& p = impulses.points[0];
    return pass(body1, body2, contact, p.bias, p.pseudo, p.mass);
}

constexpr ContactSolverHooks hooks{&prepare, &warm_start, &solve_velocity, nullptr, &solve_position};
constexpr ResponseModel model{"test-solver", nullptr, nullptr, &hooks};

/// A column of `count` balls of 1 kg and radius 0.05 m standing on the ground, each touching
/// the next, at rest.
World column(int count, const ContactSolverSettings& solver) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < count; ++i) bodies.push_back(make_sphere(1.0, 0.05, {0, 0.05 + 0.0995 * i, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = solver;
    return World(std::move(bodies), settings, model);
}

}  // namespace

TEST_CASE("A column of balls resting on the ground: each contact carries the weight above it", "[engine][contact-solver]") {
    // Solved to the solver's tolerance, the ground holds all n balls' gravity impulse n g dt,
    // each contact above one ball less, and no ball moves.
    const int n = 5;
    World world = column(n, {.velocity_iterations = 500});
    world.step();
    const auto impulses = world.contact_solver().impulses();
    REQUIRE(impulses.size() == static_cast<std::size_t>(n));
    const double g_dt = 9.81 / 60;
    std::vector<double> carried;
    for (std::size_t c = 0; c < impulses.size(); ++c) carried.push_back(impulses[c].points[0].normal);
    std::sort(carried.begin(), carried.end());
    const double tolerance = world.settings().contact_solver.tolerance;
    REQUIRE(world.contact_solver_report().velocity_passes < world.settings().contact_solver.velocity_iterations);
    // A pass that changed no velocity by more than the tolerance leaves each contact's
    // impulse within n tolerances' worth of impulse (mass 1/2 kg each) of its exact value.
    for (std::size_t k = 0; k < carried.size(); ++k) CHECK(std::abs(carried[k] - static_cast<double>(k + 1) * g_dt) <= n * tolerance);
    for (const RigidBody& body : world.bodies()) CHECK(std::abs(body.velocity.y) <= n * tolerance);
}

TEST_CASE("A column of 15 resting balls stays within 1 mm for 10 s once settled", "[engine][contact-solver]") {
    World world = column(15, {});
    for (int i = 0; i < 60; ++i) world.step();
    std::vector<Vector3> settled;
    for (const RigidBody& body : world.bodies()) settled.push_back(body.position);
    for (int i = 0; i < 600; ++i) world.step();
    for (std::size_t b = 0; b < settled.size(); ++b) CHECK(length(world.bodies()[b].position - settled[b]) <= 1e-3);
    CHECK(world.probes().kinetic() <= 1e-12);
}

TEST_CASE("The position pass moves bodies without changing their velocities", "[engine][contact-solver]") {
    // Two balls overlapping by 1 cm in free space, at rest: the pass pushes them apart and
    // leaves them at rest (no kinetic energy added), their centre of mass where it was.
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0, 0}), make_sphere(1.0, 0.05, {0.09, 0, 0})};
    WorldSettings settings{1.0 / 60, {}};
    settings.position_correction = {1.0, 0.0};
    World world(std::move(bodies), settings, model);
    world.step();
    CHECK(world.bodies()[0].velocity == Vector3{});
    CHECK(world.bodies()[1].velocity == Vector3{});
    CHECK(std::abs(world.bodies()[1].position.x - world.bodies()[0].position.x - 0.1) <= 1e-15);
    CHECK(std::abs(world.bodies()[0].position.x + world.bodies()[1].position.x - 0.09) <= 1e-15);
}

TEST_CASE("A solver responder needs discrete timing", "[engine][contact-solver]") {
    WorldSettings settings{1.0 / 60, {}};
    settings.contact_timing = ContactTiming::event;
    CHECK_THROWS_AS(World({make_sphere(1.0, 0.05, {})}, settings, model), std::invalid_argument);
}
