// The contact solver's loop (workbook/contact_solver.hpp) with test doubles for the chapter's
// functions: linear impulses along the normal at the centres, which are exact for balls in a
// column, so that the solver's answer is known in closed form. No chapter code is linked.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "workbook/contact_solver.hpp"
#include "workbook/probes.hpp"
#include "workbook/world.hpp"
#include "solver_doubles.hpp"

using namespace workbook;
using Catch::Matchers::WithinRel;

namespace {

const ResponseModel& model = testing::solver_model;

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

namespace {

/// A column of 5 resting balls and, `drop_height` m above the ground, one more ball falling
/// onto it.
World column_and_falling_ball(double drop_height, const ContactSolverSettings& solver) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < 5; ++i) bodies.push_back(make_sphere(1.0, 0.05, {0, 0.05 + 0.0995 * i, 0}));
    bodies.push_back(make_sphere(1.0, 0.05, {0, drop_height, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = solver;
    return World(std::move(bodies), settings, model);
}

}  // namespace

TEST_CASE("A resting column falls asleep: exactly at rest, its contacts no longer solved", "[engine][contact-solver][sleeping]") {
    World world = column(5, {});
    for (int i = 0; i < 120 && world.sleeping().sleeping() < 5; ++i) world.step();
    REQUIRE(world.sleeping().sleeping() == 5);
    std::vector<Vector3> asleep;
    for (const RigidBody& body : world.bodies()) asleep.push_back(body.position);
    for (int i = 0; i < 60; ++i) world.step();
    for (std::size_t b = 0; b < asleep.size(); ++b) {
        CHECK(world.bodies()[b].position == asleep[b]);
        CHECK(world.bodies()[b].velocity == Vector3{});
    }
    CHECK(world.contact_solver().impulses().empty());
    CHECK(world.contacts().size() == 5);  // still detected, to wake the column when touched
    // A velocity given to a sleeping ball from outside (a tool, a test) wakes it. Lifted off,
    // it is still within speculative reach of the ball below in the step it leaves (the
    // speculative distance, 2 cm, plus its own travel, 3 cm at 1.8 m/s: speculative_reach()),
    // so the column wakes with it; the five come to rest and fall asleep again.
    world.bodies()[4].velocity = {0, 1.8, 0};
    world.step();
    CHECK(!world.sleeping().asleep(4));
    CHECK(world.sleeping().sleeping() == 0);
    CHECK(world.bodies()[4].position.y > asleep[4].y);
    for (int i = 0; i < 240 && world.sleeping().sleeping() < 5; ++i) world.step();
    REQUIRE(world.sleeping().sleeping() == 5);
    // Pressed into the ball below, the whole column wakes at once.
    world.bodies()[4].velocity = {0, -1, 0};
    world.step();
    CHECK(world.sleeping().sleeping() == 0);
}

TEST_CASE("A world whose every body sleeps costs nothing: it skips detection and solve, and ends as if it had not",
          "[engine][contact-solver][sleeping]") {
    // Two copies of the same column; the second's bodies are handed out before every step,
    // which makes it detect and solve afresh, as every step did before the skip existed.
    World skipping = column(5, {});
    World full = column(5, {});
    int steps = 0;
    for (; steps < 240 && !skipping.at_rest(); ++steps) {
        skipping.step();
        (void)full.bodies();
        full.step();
    }
    REQUIRE(skipping.at_rest());
    REQUIRE(skipping.sleeping().sleeping() == 5);
    CHECK(!full.at_rest());  // bodies() handed out: it looked again
    for (int i = 0; i < 120; ++i) {
        skipping.step();
        CHECK(skipping.at_rest());
        (void)full.bodies();
        full.step();
    }
    const std::span<const RigidBody> a = std::as_const(skipping).bodies(), b = std::as_const(full).bodies();
    for (std::size_t k = 0; k < a.size(); ++k) {
        CHECK(a[k].position == b[k].position);
        CHECK(a[k].velocity == b[k].velocity);
        CHECK(a[k].orientation == b[k].orientation);
    }
    REQUIRE(skipping.contacts().size() == full.contacts().size());
    for (std::size_t c = 0; c < skipping.contacts().size(); ++c) {
        CHECK(skipping.contacts()[c].body1 == full.contacts()[c].body1);
        CHECK(skipping.contacts()[c].body2 == full.contacts()[c].body2);
        CHECK(skipping.contacts()[c].penetration == full.contacts()[c].penetration);
    }
    CHECK(skipping.steps_taken() == full.steps_taken());
    CHECK(skipping.time() == full.time());
    // The scene's plan says so.
    bool told = false;
    for (const StageUse& stage : skipping.plan())
        told = told || (stage.stage == "solve contacts" && stage.why.find("every body asleep detects and solves nothing") != std::string::npos);
    CHECK(told);
    // A velocity given from outside wakes the top ball: the step moves it and looks again.
    skipping.bodies()[4].velocity = {0, 1.8, 0};
    skipping.step();
    CHECK(!skipping.at_rest());
    CHECK(!skipping.sleeping().asleep(4));
}

TEST_CASE("A kinematic body that moves keeps a sleeping world looking: it is never at rest", "[engine][contact-solver][sleeping]") {
    std::vector<RigidBody> bodies;
    bodies.push_back(make_sphere(1.0, 0.05, {0, 0.05, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    RigidBody pusher = make_immovable_sphere(0.05, {-3, 0.05, 0});
    pusher.velocity = {1, 0, 0};  // reaches the ball after about 2.8 s
    bodies.push_back(pusher);
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.contact_solver = {};
    World world(std::move(bodies), settings, model);
    bool slept = false;
    for (int i = 0; i < 150; ++i) {
        world.step();
        slept = slept || world.sleeping().asleep(0);
        CHECK(!world.at_rest());
    }
    REQUIRE(slept);
    for (int i = 0; i < 60; ++i) world.step();
    CHECK(std::as_const(world).bodies()[0].position.x > 0.0);  // pushed: the pusher's contact was found
}

TEST_CASE("Sleeping off (ContactSolverSettings::sleeping): no body sleeps", "[engine][contact-solver][sleeping]") {
    World world = column(5, {.sleeping = false});
    for (int i = 0; i < 120; ++i) world.step();
    CHECK(world.sleeping().sleeping() == 0);
    CHECK(world.contact_solver().impulses().size() == 5);
}

TEST_CASE("A sleeping column wakes when a falling ball hits it, and the six balls fall asleep again",
          "[engine][contact-solver][sleeping]") {
    // The column sleeps within a second; the ball dropped from 6 m lands on it after about 1.1 s.
    World world = column_and_falling_ball(6.0, {});
    const RigidBody& ball = world.bodies()[5];
    int step = 0;
    for (; step < 600 && world.sleeping().sleeping() < 5; ++step) world.step();
    REQUIRE(world.sleeping().sleeping() == 5);
    REQUIRE(!world.sleeping().asleep(5));
    REQUIRE(ball.position.y > 1.0);  // still falling, far above the column
    // Step until the ball touches the column: the step it does, the column is awake again and
    // its top ball carries the blow.
    bool touched = false;
    for (; step < 600 && !touched; ++step) {
        world.step();
        for (const Contact& contact : world.contacts()) touched = touched || contact.body1 == 5 || contact.body2 == 5;
    }
    REQUIRE(touched);
    CHECK(world.sleeping().sleeping() == 0);
    CHECK(world.contact_solver().impulses().size() >= 6);
    // The column wakes with the impulses that held it when it fell asleep: its five contacts
    // (the ground's and four between balls) are warm started; only the new one starts cold.
    CHECK(world.contact_solver_report().warm_started_points == 5);
    // Then all six rest and sleep, the dropped ball on top of the column.
    for (; step < 1200 && world.sleeping().sleeping() < 6; ++step) world.step();
    CHECK(world.sleeping().sleeping() == 6);
    CHECK(std::abs(ball.position.y - world.bodies()[4].position.y - 0.1) <= 0.002);
    CHECK(world.probes().kinetic() == 0.0);
}

TEST_CASE("Substeps: a resting column settles where each soft contact's spring carries the weight above it",
          "[engine][contact-solver][substeps]") {
    // In the soft step (ContactSolverSettings::substeps) a resting contact stops moving when
    // its soft pass asks for no more impulse: the push bias_rate (s + slop) then balances the
    // share impulse_scale / mass_scale of the accumulated impulse k g h (k balls of 1 kg above),
    // so that s = -slop - k g / (m w^2), m the point's effective mass (1/2 kg between two balls,
    // 1 kg on the ground) and w = 2 pi hertz: the spring of the contact's frequency.
    const int n = 5;
    ContactSolverSettings solver{.substeps = 4, .contact_hertz = 30.0, .sleeping = false};
    World world = column(n, solver);
    for (int i = 0; i < 600; ++i) world.step();
    const double slop = world.settings().position_correction.slop;
    const double w = 2.0 * 3.14159265358979323846 * 30.0;
    auto overlap = [&](std::size_t below, std::size_t above) {
        const RigidBody& a = world.bodies()[below];
        const RigidBody& b = world.bodies()[above];
        return 0.1 - (b.position.y - a.position.y);
    };
    // The ground carries all n balls.
    CHECK(std::abs((0.05 - world.bodies()[0].position.y) - (slop + n * 9.81 / (1.0 * w * w))) <= 1e-6);
    for (std::size_t k = 1; k < static_cast<std::size_t>(n); ++k) {
        const auto carried = static_cast<double>(static_cast<std::size_t>(n) - k);  // balls above the contact of balls k-1 and k
        CHECK(std::abs(overlap(k - 1, k) - (slop + carried * 9.81 / (0.5 * w * w))) <= 1e-6);
    }
    for (const RigidBody& body : world.bodies()) CHECK(std::abs(body.velocity.y) <= 1e-6);
}

TEST_CASE("Substeps: a ball falling onto the ground comes to rest on it without bouncing (e = 0)",
          "[engine][contact-solver][substeps]") {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 1.0, 0}), make_immovable_plane({0, 1, 0}, {0, 0, 0})};
    bodies[0].restitution = 0.0;
    bodies[1].restitution = 0.0;
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = {.substeps = 4, .sleeping = false};
    World world(std::move(bodies), settings, model);
    for (int i = 0; i < 120; ++i) world.step();
    // At rest on a soft contact: overlap slop + g / w^2 (1 kg, 30 Hz), 1.28 mm.
    const double w = 2.0 * 3.14159265358979323846 * 30.0;
    CHECK(std::abs((0.05 - world.bodies()[0].position.y) - (0.001 + 9.81 / (w * w))) <= 1e-6);
    CHECK(std::abs(world.bodies()[0].velocity.y) <= 1e-6);
}

namespace {

/// A block of frictionless discs (spheres of 1 kg and radius 0.05 m in z = 0), `rows` rows of
/// `columns` and `columns` - 1 in turn, packed as tightly as discs pack (each in the hollow of
/// the two below, each touching its neighbours), in a box exactly `columns` discs wide, so that
/// the rows of `columns` are jammed wall to wall; solved with `solver`, without sleeping. The
/// discs start exactly touching, so the world finds no contact between them until they overlap.
World packed_discs(int columns, int rows, ContactSolverSettings solver) {
    const double r = 0.05, width = 2 * r * columns;
    std::vector<RigidBody> bodies;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns - j % 2; ++i) {
            bodies.push_back(make_sphere(1.0, r, {-width / 2 + r * (1 + 2 * i + j % 2), r + std::sqrt(3.0) * r * j, 0}));
            bodies.back().restitution = 0.0;
        }
    for (const auto& [normal, point] : {std::pair{Vector3{0, 1, 0}, Vector3{0, 0, 0}}, std::pair{Vector3{1, 0, 0}, Vector3{-width / 2, 0, 0}},
                                        std::pair{Vector3{-1, 0, 0}, Vector3{width / 2, 0, 0}}}) {
        bodies.push_back(make_immovable_plane(normal, point));
        bodies.back().restitution = 0.0;
    }
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.5, 0.002};
    solver.sleeping = false;
    settings.contact_solver = solver;
    return World(std::move(bodies), settings, model);
}

/// The packed block solved in 12 substeps of soft contacts at 180 Hz, with speculative
/// contacts of `speculative_distance` (0: none).
World block_of_discs(int columns, int rows, int relax_passes, double speculative_distance) {
    return packed_discs(columns, rows,
                        {.substeps = 12, .relax_passes = relax_passes, .contact_hertz = 180.0, .speculative_distance = speculative_distance});
}

/// The block's kinetic energy and deepest overlap after 5 s.
std::pair<double, double> block_after_5_s(World world) {
    for (int i = 0; i < 300; ++i) world.step();
    double deepest = 0.0;
    for (const Contact& contact : world.contacts()) deepest = std::max(deepest, contact.penetration);
    return {world.probes().kinetic(), deepest};
}

}  // namespace

TEST_CASE("Substeps: a packed block of discs settles at 180 Hz in 12 substeps instead of collapsing into itself",
          "[engine][contact-solver][substeps]") {
    // 8 discs wide and 16 rows high (120 discs). Without speculative contacts, with one relax
    // pass a substep, part of each substep's push stays in the velocities, and the block,
    // dropping onto its contacts as they appear, gathers speed until it collapses into itself:
    // after 5 s 23 J, and two discs 4.5 cm into each other (measured). With two passes (the
    // default) it rests on its contacts' springs: 3e-6 J, the deepest overlap 4.9 mm. The
    // bounds sit between the two.
    const auto [kinetic, deepest] = block_after_5_s(block_of_discs(8, 16, ContactSolverSettings{}.relax_passes, 0.0));
    CHECK(kinetic < 1e-4);
    CHECK(deepest < 0.01);
    // Speculative contacts (on by default) stop the drop onto contacts not yet found: then one
    // relax pass, Box2D's, rests too (2.6e-6 J, 4.9 mm, measured).
    const auto [kinetic_one, deepest_one] = block_after_5_s(block_of_discs(8, 16, 1, ContactSolverSettings{}.speculative_distance));
    CHECK(kinetic_one < 1e-4);
    CHECK(deepest_one < 0.01);
}

TEST_CASE("Substeps: a ball that wakes when another runs into it starts its substeps where it slept",
          "[engine][contact-solver][substeps]") {
    // Ball 0 sleeps on the ground; ball 1 slides along the ground (frictionless) into it from
    // the side. The step in which ball 0 wakes did not move it or give it gravity (it slept
    // through the move), so the substeps must not take a move and a kick back out of it: its
    // height, where its soft contact with the ground carries its weight, stays put.
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0.05, 0}), make_sphere(1.0, 0.05, {-0.5, 0.05, 0}, {0.5, 0, 0}),
                                  make_immovable_plane({0, 1, 0}, {0, 0, 0})};
    for (RigidBody& body : bodies) body.restitution = 0.0;
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    // Without speculative contacts, so that ball 0 wakes in the step that pushes it, not a
    // step earlier when ball 1 comes within the distance.
    settings.contact_solver = {.substeps = 4, .speculative_distance = 0.0};
    World world(std::move(bodies), settings, model);
    double resting_height = 0.0;
    bool woke = false;
    for (int i = 0; i < 120 && !woke; ++i) {
        const bool was_asleep = world.sleeping().asleep(0);
        if (was_asleep) resting_height = world.bodies()[0].position.y;
        world.step();
        woke = was_asleep && !world.sleeping().asleep(0);
    }
    REQUIRE(woke);
    // The push is horizontal (the centres at equal heights), so the ball's height changes only
    // because its island wakes cold, without last step's impulse on the ground: it falls for
    // at most one substep before its contact holds it again, g h^2 = 0.17 mm with h = dt / 4.
    // A move and a kick taken back that it never had shift it by 1.1 mm.
    const double h = settings.time_step / 4;
    CHECK(std::abs(world.bodies()[0].position.y - resting_height) <= 9.81 * h * h);
    CHECK(world.bodies()[0].velocity.x > 0.0);
}


namespace {

/// Two balls of 1 kg and radius 0.05 m in free space under gravity, one 9.9 cm above the other
/// (overlapping by 1 mm), moving up at `lower` and `upper` m/s; their contact solved by one
/// shock sweep alone (no passes, no overlap removed).
World two_balls_one_sweep(double lower, double upper) {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0, 0}, {0, lower, 0}), make_sphere(1.0, 0.05, {0, 0.099, 0}, {0, upper, 0})};
    for (RigidBody& body : bodies) body.restitution = 0.0;
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = {.velocity_iterations = 0, .position_iterations = 0, .shock_sweeps = 1, .sleeping = false};
    return World(std::move(bodies), settings, model);
}

/// The packed block solved in one rigid solve a step of at most 15 passes each, with `sweeps`
/// shock sweeps.
World jammed_block(int columns, int rows, int sweeps) {
    return packed_discs(columns, rows, {.velocity_iterations = 15, .position_iterations = 15, .shock_sweeps = sweeps});
}
}  // namespace


namespace {

/// The doubles' functions, with a prepare that records the shallowest depth it was handed:
/// the chapter's functions must never see a negative one (their legal domain).
double shallowest_seen = 0.0;
void recording_prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                       const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    for (std::size_t i = 0; i < contact.point_count; ++i)
        shallowest_seen = std::min(shallowest_seen, contact.points[i].penetration);
    testing::prepare(body1, body2, contact, impulses, settings, knobs, dt);
}
constexpr ContactSolverHooks recording_hooks{&recording_prepare, &testing::warm_start, &testing::solve_velocity, nullptr,
                                             &testing::solve_position};
constexpr ResponseModel recording_model{"test-solver-recording", nullptr, nullptr, &recording_hooks};

/// Without gravity, along x: ball A touching ball B and moving into it at 2.4 m/s (4 cm a
/// step, less than a radius: no swept test), and ball C at rest 2 mm beyond B. All 1 kg,
/// radius 0.05 m, e = 0; `pushes` pushes the overlap out completely, beyond no slop.
World row_of_three(const ContactSolverSettings& solver) {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {-0.1, 0, 0}), make_sphere(1.0, 0.05, {0, 0, 0}),
                                  make_sphere(1.0, 0.05, {0.102, 0, 0})};
    bodies[0].velocity = {2.4, 0, 0};
    WorldSettings settings{1.0 / 60, {}};
    settings.position_correction = {1.0, 0.0};
    settings.contact_solver = solver;
    return World(std::move(bodies), settings, recording_model);
}

double deepest_overlap(const World& world) {
    double deepest = 0.0;
    const auto bodies = world.bodies();
    for (std::size_t a = 0; a < bodies.size(); ++a)
        for (std::size_t b = a + 1; b < bodies.size(); ++b)
            deepest = std::max(deepest, bodies[a].shape.radius + bodies[b].shape.radius - length(bodies[a].position - bodies[b].position));
    return deepest;
}

}  // namespace

TEST_CASE("Shock sweep: a ball coming down onto a lower one stops on it and the lower one does not move",
          "[engine][contact-solver][shock]") {
    // The move gave both gravity's g dt; the upper ball comes down at 1 m/s more. With the
    // lower one frozen the sweep gives the upper one the lower one's velocity and leaves the
    // lower one as the move left it (a two-sided solve would have shared the 1 m/s).
    World world = two_balls_one_sweep(0.0, -1.0);
    world.step();
    REQUIRE(world.contacts().size() == 1);
    const double g_dt = 9.81 * (1.0 / 60);
    CHECK(std::abs(world.bodies()[0].velocity.y + g_dt) <= 1e-15);
    CHECK(std::abs(world.bodies()[1].velocity.y - world.bodies()[0].velocity.y) <= 1e-15);
    CHECK(world.probes().response_energy_change < 0.0);
}

TEST_CASE("Shock sweep: a lower ball moving up into an upper one is solved two-sided, adding no kinetic energy",
          "[engine][contact-solver][shock]") {
    // Frozen, the lower ball would lift the upper one to its own 1 m/s: 0.5 J more (less
    // gravity's share). The sweep solves that contact two-sided instead: both end at the mean
    // velocity, 1/2 m/s - g dt, and the solve takes energy out.
    World world = two_balls_one_sweep(1.0, 0.0);
    world.step();
    REQUIRE(world.contacts().size() == 1);
    const double g_dt = 9.81 * (1.0 / 60);
    CHECK(std::abs(world.bodies()[0].velocity.y - (0.5 - g_dt)) <= 1e-15);
    CHECK(std::abs(world.bodies()[1].velocity.y - (0.5 - g_dt)) <= 1e-15);
    CHECK(world.probes().response_energy_change < 0.0);
}

TEST_CASE("Shock sweep: a packed block of balls jammed wall to wall comes to rest at 15 passes",
          "[engine][contact-solver][shock]") {
    // 20 balls wide and 30 rows high (585 balls), started touching. At 15 passes alone the
    // jammed rows never settle: after 10 s 5.5 J and two balls 4.9 cm into each other
    // (measured; at 100 passes of each kind, 560 J and 14 cm). With one sweep after the
    // velocity passes: 3e-11 J, the deepest overlap 4.73 mm (the slop plus what the position
    // passes leave). The bounds sit just above.
    World world = jammed_block(20, 30, 1);
    for (int i = 0; i < 600; ++i) world.step();
    double deepest = 0.0;
    for (const Contact& contact : world.contacts()) deepest = std::max(deepest, contact.penetration);
    CHECK(world.probes().kinetic() < 1e-8);
    CHECK(deepest < 0.005);
}

TEST_CASE("Speculative contacts: a ball pushed into a neighbour it does not touch yet stops touching it, not in it",
          "[engine][contact-solver][speculative]") {
    // A runs into B, and B, pushed at 1.2 m/s (2 cm a step), into C 2 mm away. Without
    // speculative contacts B-C is no contact in that step and B ends 1.8 cm deep in C. With a
    // speculative distance of 1 cm it is one: B-C may close its gap (0.12 m/s) and no more, so
    // the inelastic solve gives A and B 0.84 m/s and C 0.72 m/s, and the step ends with every
    // pair touching to rounding. Kinetic energy falls from 2.88 J to 0.965 J.
    World without = row_of_three({.sleeping = false, .speculative_distance = 0.0});
    without.step();
    CHECK(deepest_overlap(without) > 0.017);

    shallowest_seen = 0.0;
    World with = row_of_three({.sleeping = false, .speculative_distance = 0.01});
    const double before = with.probes().kinetic();
    with.step();
    const auto bodies = with.bodies();
    CHECK(std::abs(bodies[0].velocity.x - 0.84) <= 1e-9);
    CHECK(std::abs(bodies[1].velocity.x - 0.84) <= 1e-9);
    CHECK(std::abs(bodies[2].velocity.x - 0.72) <= 1e-9);
    // Each pair's gap is a difference of positions of order 0.1 m: rounding leaves ~1e-17.
    CHECK(deepest_overlap(with) <= 1e-12);
    CHECK(std::abs(length(bodies[2].position - bodies[1].position) - 0.1) <= 1e-12);
    CHECK(with.probes().kinetic() < before);
    CHECK(shallowest_seen == 0.0);  // the chapter's functions saw no negative depth
    // The solve took the pair's velocities to within the tolerance, so the next steps leave
    // them touching: nothing pulls them apart, nothing pushes them together.
    for (int i = 0; i < 60; ++i) with.step();
    CHECK(deepest_overlap(with) <= 1e-9);
    CHECK(with.probes().kinetic() <= before);
}

TEST_CASE("Speculative contacts: a gap is never pushed, and two balls at rest a gap apart stay where they are",
          "[engine][contact-solver][speculative]") {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0, 0}), make_sphere(1.0, 0.05, {0.105, 0, 0})};
    WorldSettings settings{1.0 / 60, {}};
    settings.position_correction = {1.0, 0.0};
    settings.contact_solver = {.sleeping = false, .speculative_distance = 0.01};
    shallowest_seen = 0.0;
    World world(std::move(bodies), settings, recording_model);
    for (int i = 0; i < 60; ++i) world.step();
    REQUIRE(world.contacts().size() == 1);
    CHECK(std::abs(world.contacts()[0].points[0].penetration + 0.005) <= 1e-15);  // the gap, as a negative depth
    CHECK(world.contacts()[0].penetration == 0.0);                                // the deepest overlap: none
    CHECK(world.bodies()[0].position == Vector3{0, 0, 0});
    CHECK(world.bodies()[1].position == Vector3{0.105, 0, 0});
    CHECK(world.bodies()[0].velocity == Vector3{});
    CHECK(world.bodies()[1].velocity == Vector3{});
    CHECK(shallowest_seen == 0.0);
}

namespace {

/// The engine tests' stand-in for the chapter's prepare() with the bounce: Newton's
/// restitution, e the smaller of the two coefficients, above the bounce threshold.
void bouncing_prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                      const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    testing::prepare(body1, body2, contact, impulses, settings, knobs, dt);
    const double u = testing::normal_velocity(body1, body2, contact);
    impulses.points[0].bounce = u < -settings.bounce_threshold ? -std::min(body1.restitution, body2.restitution) * u : 0.0;
}

constexpr ContactSolverHooks bouncing_hooks{&bouncing_prepare, &testing::warm_start, &testing::solve_velocity, nullptr,
                                            &testing::solve_position};
constexpr ResponseModel bouncing_model{"test-solver-bouncing", nullptr, nullptr, &bouncing_hooks};

}  // namespace

TEST_CASE("Speculative contacts bounce: a ball with e = 1 that its speculative contact meets leaves with the speed it came at",
          "[engine][contact-solver][speculative]") {
    // Dropped from heights a few millimetres apart, a ball reaches the ground in its last step
    // of fall either overlapping it or still a gap above it (within the speculative distance).
    // Either way the bounce sends it back up at the speed it came down at: stopped at the gap
    // instead, it would arrive touching at gap / dt and bounce back at that.
    const double g = 9.81, dt = 1.0 / 60;
    for (const int substeps : {0, 4})
    for (const double height : {1.0, 1.004, 1.008, 1.013, 1.02, 1.027}) {
        CAPTURE(substeps, height);
        std::vector<RigidBody> bodies{make_sphere(1.0, 0.1, {0, height, 0}), make_immovable_plane({0, 1, 0}, {0, 0, 0})};
        for (RigidBody& body : bodies) body.restitution = 1.0;
        WorldSettings settings{dt, {0, -g, 0}};
        settings.contact_solver.sleeping = false;
        settings.contact_solver.substeps = substeps;
        World world(std::move(bodies), settings, bouncing_model);
        double before = 0.0;
        for (int step = 0; step < 60 && !(world.bodies()[0].velocity.y > 0.0); ++step) {
            before = world.bodies()[0].velocity.y;
            world.step();
        }
        const double after = world.bodies()[0].velocity.y;
        // It came at its speed of the step before plus the step's g dt.
        const double came = -(before - g * dt);
        CHECK(came > 4.0);
        CHECK_THAT(after, WithinRel(came, 1e-12));
    }
}

TEST_CASE("Speculative contacts in substeps: the ball pushed into a neighbour stops touching it",
          "[engine][contact-solver][speculative][substeps]") {
    // The row of three above in four substeps: A's overlap with B is a soft contact pushed out
    // over some steps, but B-C closes its gap and hardly more. The substeps make a fixed number
    // of passes, not passes to a tolerance: the three here leave B 0.09 mm in C (without
    // speculative contacts 1.8 cm), under a millimetre, half the slop of the chapter's pile.
    World without = row_of_three({.substeps = 4, .sleeping = false, .speculative_distance = 0.0});
    without.step();
    CHECK(deepest_overlap(without) > 0.01);
    shallowest_seen = 0.0;
    World with = row_of_three({.substeps = 4, .sleeping = false, .speculative_distance = 0.01});
    const double before = with.probes().kinetic();
    with.step();
    const auto bodies = with.bodies();
    const double bc = 0.1 - length(bodies[2].position - bodies[1].position);
    CHECK(bc < 0.001);
    CHECK(with.probes().kinetic() < before);
    CHECK(shallowest_seen == 0.0);
}

namespace {

/// A column of `count` balls of 1 kg and radius 0.05 m, e = 0, 2 cm apart one above the
/// other and the lowest 1 cm above the ground (the bench's pile, one column of it), dropped
/// under gravity for `steps` steps at 60 Hz with the solver's defaults. Returns the deepest
/// overlap of two balls, or of a ball and the ground, after any step.
double deepest_while_landing(int count, int steps, bool swept) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < count; ++i) bodies.push_back(make_sphere(1.0, 0.05, {0, 0.06 + 0.12 * i, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    for (RigidBody& body : bodies) body.restitution = 0.0;
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.5, 0.002};
    settings.swept_spheres = swept;
    World world(std::move(bodies), settings, model);
    double deepest = 0.0;
    for (int step = 0; step < steps; ++step) {
        world.step();
        const auto balls = world.bodies().first(static_cast<std::size_t>(count));
        deepest = std::max(deepest, 0.05 - balls[0].position.y);
        for (std::size_t k = 0; k + 1 < balls.size(); ++k)
            deepest = std::max(deepest, 0.1 - length(balls[k + 1].position - balls[k].position));
    }
    return deepest;
}

/// A column of `count` cubes of 10 cm and 1 kg, 2 cm apart one above the other and the lowest
/// 2 cm above the ground, dropped for `steps` steps at 60 Hz with the solver's defaults but
/// the speculative distance. Returns the deepest overlap of two cubes, or of a cube and the
/// ground, after any step (the cubes fall straight and stay upright).
double deepest_box_landing(int count, int steps, double speculative_distance) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < count; ++i) bodies.push_back(make_box(1.0, {0.05, 0.05, 0.05}, {0, 0.07 + 0.12 * i, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    for (RigidBody& body : bodies) body.restitution = 0.0;
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.5, 0.002};
    settings.contact_solver.speculative_distance = speculative_distance;
    World world(std::move(bodies), settings, model);
    double deepest = 0.0;
    for (int step = 0; step < steps; ++step) {
        world.step();
        const auto boxes = world.bodies().first(static_cast<std::size_t>(count));
        deepest = std::max(deepest, 0.05 - boxes[0].position.y);
        for (std::size_t k = 0; k + 1 < boxes.size(); ++k) deepest = std::max(deepest, 0.1 - (boxes[k + 1].position.y - boxes[k].position.y));
    }
    return deepest;
}

}  // namespace

TEST_CASE("Speculative contacts reach as far as a ball travels: a dropped column lands without passing into itself",
          "[engine][contact-solver][speculative]") {
    // The column closes up from the bottom: each ball stops on the one below while the ones above
    // still fall, at up to 5 m/s by the top. A ball the solve stops closes its 2 cm gap to the
    // ball above by that ball's speed times the step (8 cm at 5 m/s), far beyond the
    // speculative distance: found only within that distance, the pair is no contact in that
    // step and the balls end it centimetres into each other (without the swept test, whose
    // travels the reach adds). Found within the distance plus both balls' travel, every such
    // pair is solved with the rest (and the shock sweep stops each ball on the one below), and
    // the balls end every step touching to rounding: heights up to 7 m, rounded to about 1e-15 m
    // in each of 120 steps.
    const double without = deepest_while_landing(60, 120, false);
    const double with = deepest_while_landing(60, 120, true);
    INFO("without the travels " << without << " m, with them " << with << " m");
    CHECK(without > 0.09);  // nearly a diameter, as chapter 5's page says
    CHECK(with <= 1e-12);
}

TEST_CASE("Speculative points for boxes: a dropped column of cubes lands without passing into itself",
          "[engine][contact-solver][speculative][box]") {
    // As the column of balls above: a cube that the solve stops on the one below closes its
    // gap to the cube above, still falling, by that cube's speed times the step. Without
    // speculative points the pair is no contact in that step and the cubes end it centimetres
    // into each other (4.3 cm at the deepest in the first second); with them (the distance and
    // both cubes' travels, as for balls) the pair is solved with the rest, and the cubes end
    // every step touching to rounding (heights up to 1.2 m).
    const double without = deepest_box_landing(10, 60, 0.0);
    const double with = deepest_box_landing(10, 60, ContactSolverSettings{}.speculative_distance);
    INFO("without speculative points " << without << " m, with them " << with << " m");
    CHECK(without > 0.03);
    CHECK(with <= 1e-12);
}

TEST_CASE("Speculative contacts: the grid finds the pairs a test of every pair finds, with the swept test on or off",
          "[engine][contact-solver][speculative]") {
    // Twenty balls in a row 1 cm apart (within the speculative distance of 2 cm), the odd ones
    // moving: enough bodies for the grid, whose walk must count the distance (and, with the
    // swept test, the travels) as the narrow phase does.
    for (const bool swept : {false, true}) {
        std::vector<RigidBody> bodies;
        for (int i = 0; i < 20; ++i) {
            bodies.push_back(make_sphere(1.0, 0.05, {0.11 * i, 0, 0}));
            if (i % 2 == 1) bodies.back().velocity = {0, 0.9, 0};
        }
        WorldSettings settings{1.0 / 60, {}};
        settings.swept_spheres = swept;
        World grid(bodies, settings, model);
        World every_pair(bodies, settings, model);
        every_pair.set_shortcuts({.broad_phase = false});
        grid.step();
        every_pair.step();
        INFO("swept test " << (swept ? "on" : "off"));
        CHECK(grid.used_broad_phase());
        REQUIRE(grid.contacts().size() == every_pair.contacts().size());
        CHECK(grid.contacts().size() >= 19);  // every neighbour pair, and with travels more
        for (std::size_t c = 0; c < grid.contacts().size(); ++c) {
            CHECK(grid.contacts()[c].body1 == every_pair.contacts()[c].body1);
            CHECK(grid.contacts()[c].body2 == every_pair.contacts()[c].body2);
        }
    }
}

namespace {

/// A ball of 20 kg resting on a ball of 1 kg on a frictionless ground, both sliding along it at
/// `speed` (m/s), solved in a few passes without a shock sweep: the warm start alone carries
/// the heavy ball's weight from one step to the next (cold, three passes leave most of it
/// unsolved: each pass hands the light ball a share of what the heavy one still asks).
World heavy_on_light(double speed) {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0.05, 0}), make_sphere(20.0, 0.05, {0, 0.1495, 0})};
    for (RigidBody& ball : bodies) ball.velocity = {speed, 0, 0};
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    WorldSettings settings{1.0 / 60, {0, -9.81, 0}};
    settings.position_correction = {0.2, 0.001};
    settings.contact_solver = {.velocity_iterations = 3, .shock_sweeps = 0, .sleeping = false};
    return World(std::move(bodies), settings, model);
}

}  // namespace

TEST_CASE("Warm start: balls sliding faster than the match distance a step rest on each other as balls standing still do",
          "[engine][contact-solver]") {
    // At 1.5 m/s every contact point moves 2.5 cm a step, more than match_distance (1 cm). A pair
    // of balls, or a ball and a plane, touches at one point, found by the pair: the sliding
    // column is warm started as the standing one is, and its vertical motion is the same step
    // for step (the sideways speed changes nothing along the vertical normals). Matched by
    // distance, the sliding column started cold every step: from the second step on its balls'
    // vertical speeds differed from the standing column's by 0.019 m/s and their heights by
    // 0.26 mm (measured).
    World standing = heavy_on_light(0.0);
    World sliding = heavy_on_light(1.5);
    for (int step = 0; step < 60; ++step) {
        standing.step();
        sliding.step();
        for (std::size_t i = 0; i < 2; ++i) {
            CHECK(std::abs(sliding.bodies()[i].velocity.y - standing.bodies()[i].velocity.y) <= 1e-12);
            CHECK(std::abs(sliding.bodies()[i].position.y - standing.bodies()[i].position.y) <= 1e-12);
        }
    }
    CHECK(sliding.contact_solver_report().warm_started_points == 2);
}
