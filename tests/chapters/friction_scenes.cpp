// Chapter 6's scenes against their closed forms (chapters/friction/scenes, written by
// tools/scenes/friction.py), run with the reference solver:
// 1. a block on a 30 degree incline sticks when tan 30 <= mu_s, and slides at
//    a = g (sin - mu cos) otherwise;
// 2. a box sliding on the ground stops after v0^2 / (2 mu g);
// 3. a ball thrown without spin rolls at 5/7 of its speed from t = 2 v0 / (7 mu g); with
//    backspin it comes back;
// 4. no step of any of them adds energy;
// 5. chapter 5's stack of ten boxes, with friction, rests: once settled (5 s), no box moves more
//    than 1 mm over the rest of the minute and no contact is deeper than the slop;
// 6. a stack of thirty boxes with friction stands on the solver's default passes (the shock
//    sweep solves each box against the one below it, friction included);
// 7. a speculative point's target is no bounce: without a bounce the passes run one phase.
//
// Tolerances. The solver stops its passes when a pass changes no point's velocity by more than
// settings.tolerance (1e-9 m/s), so a velocity that should be 0 is within that of it, and a
// position drifts by at most that times the duration; a sliding block's friction is mu times
// a normal impulse known to that tolerance, so its speed may be off by that much a step. A
// ball has one contact point, solved exactly: a few ulps of its speed a step.
// Semi-implicit Euler moves each step with the velocity at the step's end, so distances differ
// from the closed forms of continuous time by at most v0 dt / 2 + a dt^2 / 2; a ball's contact
// point lies halfway into one step's fall of g dt^2, so its lever arm is R - g dt^2 / 2, and
// the motion is predicted with that arm (and compared with the closed form within the
// difference the arm makes).
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "friction.hpp"
#include "sanitized_run.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/probes.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"
#include "workbook/world.hpp"

using namespace workbook;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double g = 9.81;

Scene friction_scene(const std::string& name) {
    return load_scene(std::string(WORKBOOK_SOURCE_DIR) + "/chapters/friction/scenes/" + name + ".json");
}

World world_of(const Scene& scene) { return make_world(scene, *find_response_model(scene.responder)); }

std::size_t steps_of(const Scene& scene) { return step_count(scene.duration, scene.settings.time_step); }

/// The first body of every scene is the one that moves.
const RigidBody& mover(const World& world) { return world.bodies()[0]; }

/// Distance travelled under semi-implicit Euler by a body decelerated by `a` from `v0` until a
/// step would reverse it (it then sticks): x += v dt with each step's final velocity.
double discrete_stopping_distance(double v0, double a, double dt) {
    double v = v0, x = 0.0;
    while (v > a * dt) {
        v -= a * dt;
        x += v * dt;
    }
    return x;
}

}  // namespace

TEST_CASE("a block on a 30 degree incline with mu_s 0.7 sticks; with mu_s = mu_d = 0.5 it slides", "[friction]") {
    const double theta = std::numbers::pi / 6;
    Scene scene = friction_scene("block-on-incline-sticks");
    REQUIRE(scene.bodies[0].static_friction == 0.7);
    REQUIRE(scene.bodies[0].friction == 0.5);
    REQUIRE(std::tan(theta) <= 0.7);
    World world = world_of(scene);
    const Vector3 start = mover(world).position;
    const std::size_t steps = steps_of(scene);
    double fastest = 0.0;
    for (std::size_t i = 0; i < steps; ++i) {
        world.step();
        fastest = std::max(fastest, length(mover(world).velocity));
    }
    const double tolerance = scene.settings.contact_solver.tolerance;
    CHECK(fastest <= 4 * tolerance);
    CHECK(length(mover(world).position - start) <= scene.duration * 4 * tolerance);

    // The same block whose static coefficient is only its dynamic one, 0.5 < tan 30: it slides.
    for (RigidBody& body : scene.bodies) body.static_friction = body.friction;
    World sliding = world_of(scene);
    for (std::size_t i = 0; i < steps; ++i) sliding.step();
    const Vector3 downhill{std::cos(theta), 0, -std::sin(theta)};
    const double a = g * (std::sin(theta) - 0.5 * std::cos(theta));
    CHECK(std::abs(dot(mover(sliding).velocity, downhill) - a * scene.duration) <= static_cast<double>(steps) * tolerance);
}

TEST_CASE("a block on a 30 degree incline with mu 0.3 slides at g (sin - mu cos)", "[friction]") {
    const double theta = std::numbers::pi / 6, mu = 0.3;
    const Scene scene = friction_scene("block-on-incline-slides");
    REQUIRE(scene.bodies[0].friction == mu);
    World world = world_of(scene);
    const Vector3 start = mover(world).position;
    const Vector3 downhill{std::cos(theta), 0, -std::sin(theta)};
    const Vector3 up_slope_normal{std::sin(theta), 0, std::cos(theta)};
    const double a = g * (std::sin(theta) - mu * std::cos(theta));
    const double dt = scene.settings.time_step;
    const std::size_t steps = steps_of(scene);
    const double tolerance = scene.settings.contact_solver.tolerance;
    for (std::size_t i = 1; i <= steps; ++i) {
        world.step();
        const double n = static_cast<double>(i);
        const double v = a * n * dt;
        // Each step adds a dt along the slope: the clamp gives mu times the normal impulse,
        // m g cos dt to the solver's tolerance.
        REQUIRE(std::abs(dot(mover(world).velocity, downhill) - v) <= n * tolerance);
        REQUIRE(std::abs(dot(mover(world).velocity, up_slope_normal)) <= n * tolerance);
    }
    // x_n = a dt^2 n (n + 1) / 2 for semi-implicit Euler; within a dt t / 2 of a t^2 / 2.
    const double n = static_cast<double>(steps);
    const double travelled = dot(mover(world).position - start, downhill);
    const double discrete = a * dt * dt * n * (n + 1) / 2;
    CHECK(std::abs(travelled - discrete) <= n * tolerance * scene.duration);
    CHECK(std::abs(travelled - a * scene.duration * scene.duration / 2) <= a * dt * scene.duration / 2 * (1 + 1e-9));
}

TEST_CASE("a box sliding at 3 m/s with mu 0.5 stops after v^2 / (2 mu g) and stays", "[friction]") {
    const double mu = 0.5, v0 = 3.0;
    const Scene scene = friction_scene("box-sliding-to-rest");
    REQUIRE(scene.bodies[0].friction == mu);
    REQUIRE(scene.bodies[0].velocity.x == v0);
    World world = world_of(scene);
    const double start = mover(world).position.x;
    const double a = mu * g, dt = scene.settings.time_step;
    double stopped_at = -1.0;
    for (std::size_t i = 1; i <= steps_of(scene); ++i) {
        world.step();
        if (stopped_at < 0 && std::abs(mover(world).velocity.x) <= 4 * scene.settings.contact_solver.tolerance)
            stopped_at = world.time();
    }
    const double travelled = mover(world).position.x - start;
    const double closed = v0 * v0 / (2 * a);
    CHECK(std::abs(travelled - discrete_stopping_distance(v0, a, dt)) <= 1e-9 * closed);
    CHECK(closed - travelled >= 0.0);
    CHECK(closed - travelled <= v0 * dt / 2 + a * dt * dt / 2);
    // It stops in the step that holds v0 / (mu g), and then stays.
    CHECK(stopped_at >= v0 / a);
    CHECK(stopped_at <= v0 / a + dt * (1 + 1e-9));
    CHECK(length(mover(world).velocity) <= 4 * scene.settings.contact_solver.tolerance);
}

namespace {

/// A ball's motion on the ground: speed (+x) and spin about +y (positive when it rolls forward).
struct Rolling {
    double speed, spin;
};

/// The ball's final rolling speed: the angular momentum about the contact point,
/// m v r + I w, is kept by friction (it acts at the point), and rolling is v = w r.
double rolling_speed(Rolling start, double m, double inertia, double arm) {
    return (m * start.speed * arm + inertia * start.spin) / (m * arm + inertia / arm);
}

/// When the slip v - w r reaches 0: friction mu m g takes mu g (1 + m r^2 / I) off it each second.
double switch_time(Rolling start, double mu, double m, double inertia, double arm) {
    return (start.speed - start.spin * arm) / (mu * g * (1 + m * arm * arm / inertia));
}

void check_ball(const std::string& name, Rolling start, double expected_closed_form_speed, double expected_switch) {
    const Scene scene = friction_scene(name);
    const RigidBody& ball = scene.bodies[0];
    const double m = ball.mass(), radius = ball.shape.radius, mu = ball.friction;
    const double inertia = 0.4 * m * radius * radius;
    const double dt = scene.settings.time_step;
    REQUIRE(ball.velocity.x == start.speed);
    REQUIRE(ball.angular_velocity.y == start.spin);
    // The contact point lies halfway into the step's fall of g dt^2 below the ball.
    const double arm = radius - g * dt * dt / 2;
    World world = world_of(scene);
    double switched = -1.0;
    for (std::size_t i = 1; i <= steps_of(scene); ++i) {
        world.step();
        const double slip = mover(world).velocity.x - mover(world).angular_velocity.y * arm;
        if (switched < 0 && std::abs(slip) <= 4 * scene.settings.contact_solver.tolerance) switched = world.time();
        if (switched >= 0) REQUIRE(std::abs(slip) <= 4 * scene.settings.contact_solver.tolerance);
    }
    const double steps = static_cast<double>(steps_of(scene));
    const double predicted = rolling_speed(start, m, inertia, arm);
    CHECK(std::abs(mover(world).velocity.x - predicted) <= steps * 64 * eps * std::abs(start.speed));
    // The closed form of continuous time, with the lever arm R: within what the arm changes.
    CHECK(std::abs(rolling_speed(start, m, inertia, radius) - expected_closed_form_speed) <= 16 * eps * std::abs(start.speed));
    // The shorter arm changes the final speed by less than 2 (g dt^2 / 2) / R of the speeds in play.
    CHECK(std::abs(mover(world).velocity.x - expected_closed_form_speed) <=
          2 * (g * dt * dt / 2) / radius * (std::abs(start.speed) + radius * std::abs(start.spin)));
    // It starts to roll in the step that holds the switch.
    const double t = switch_time(start, mu, m, inertia, arm);
    CHECK(switched >= t - 1e-9);
    CHECK(switched <= t + dt * (1 + 1e-9));
    CHECK(std::abs(switch_time(start, mu, m, inertia, radius) - expected_switch) <= 16 * eps * expected_switch);
}

}  // namespace

TEST_CASE("a ball thrown at 3.5 m/s without spin, mu 0.2, rolls at 5/7 of it from 2 v0 / (7 mu g)", "[friction]") {
    const double v0 = 3.5, mu = 0.2;
    check_ball("ball-starts-rolling", {v0, 0.0}, 5.0 / 7.0 * v0, 2 * v0 / (7 * mu * g));
}

TEST_CASE("a ball at 2 m/s with 60 rad/s of backspin, mu 0.2, comes back at -2/7 m/s", "[friction]") {
    const double v0 = 2.0, w0 = -60.0, r = 0.1, mu = 0.2;
    check_ball("ball-with-backspin", {v0, w0}, (5 * v0 + 2 * r * w0) / 7, 2 * (v0 - r * w0) / (7 * mu * g));
    CHECK((5 * v0 + 2 * r * w0) / 7 < 0.0);
}

TEST_CASE("no step of a friction scene adds energy", "[friction]") {
    for (const char* name : {"block-on-incline-sticks", "block-on-incline-slides", "box-sliding-to-rest",
                             "ball-starts-rolling", "ball-with-backspin", "rod-lands-on-its-end"}) {
        CAPTURE(name);
        const Scene scene = friction_scene(name);
        // A body that bounces (the rod, e = 1) is also moved within the step by the solve's
        // change of its velocity, up at a landing, which adds potential energy: its total
        // energy is checked over the scene, its kinetic energy at every step.
        const bool bounces = scene.bodies[0].restitution > 0.0;
        World world = world_of(scene);
        const double m = mover(world).mass(), dt = scene.settings.time_step;
        // The position pass may lift the body by what the velocity passes left of the step's
        // overlap, at most their tolerance times dt: m g of that is all the energy it can add.
        const double lift = m * g * scene.settings.contact_solver.tolerance * dt;
        const double first = world.probes().total_energy();
        double before = first;
        double largest_rise = -std::numeric_limits<double>::infinity(), largest_response = largest_rise;
        for (std::size_t i = 0; i < steps_of(scene); ++i) {
            world.step();
            const Probes p = world.probes();
            largest_rise = std::max(largest_rise, p.total_energy() - before - lift - 16 * eps * std::abs(before));
            largest_response = std::max(largest_response, p.response_energy_change - 16 * eps * p.kinetic());
            before = p.total_energy();
        }
        if (!bounces) CHECK(largest_rise <= 0.0);
        CHECK(world.probes().total_energy() <= first + static_cast<double>(steps_of(scene)) * lift + 16 * eps * first);
        CHECK(largest_response <= 0.0);
    }
}

TEST_CASE("without friction the responder friction bounces exactly as resting-contact", "[friction]") {
    // Two balls dropped on the ground with e = 0.8: the bounce comes in one phase, as in chapter 5.
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.1, {0, 0, 0.5}), make_sphere(2.0, 0.1, {0.05, 0, 0.9}),
                                  make_immovable_plane({0, 0, 1}, {0, 0, 0})};
    for (RigidBody& body : bodies) body.restitution = 0.8;
    const WorldSettings settings{1.0 / 240, {0, 0, -g}};
    World plain(bodies, settings, *find_response_model("resting-contact"));
    World with_friction_pass(bodies, settings, *find_response_model("friction"));
    for (int i = 0; i < 480; ++i) {
        plain.step();
        with_friction_pass.step();
    }
    for (std::size_t b = 0; b < 2; ++b) {
        CAPTURE(b);
        CHECK(plain.bodies()[b].position == with_friction_pass.bodies()[b].position);
        CHECK(plain.bodies()[b].velocity == with_friction_pass.bodies()[b].velocity);
    }
}

TEST_CASE("without friction the responder friction moves the bodies exactly as resting-contact", "[friction]") {
    const Scene scene = load_scene(std::string(WORKBOOK_SOURCE_DIR) + "/chapters/resting-contact/scenes/pyramid-of-balls.json");
    REQUIRE(scene.responder == "resting-contact");
    World plain = make_world(scene, *find_response_model("resting-contact"));
    World with_friction_pass = make_world(scene, *find_response_model("friction"));
    const std::size_t steps = std::min<std::size_t>(steps_of(scene), 240);
    for (std::size_t i = 0; i < steps; ++i) {
        plain.step();
        with_friction_pass.step();
    }
    for (std::size_t b = 0; b < plain.bodies().size(); ++b) {
        CAPTURE(b);
        CHECK(plain.bodies()[b].position == with_friction_pass.bodies()[b].position);
        CHECK(plain.bodies()[b].velocity == with_friction_pass.bodies()[b].velocity);
        CHECK(plain.bodies()[b].angular_velocity == with_friction_pass.bodies()[b].angular_velocity);
    }
}

TEST_CASE("the engine's friction_tangents, which warm starts friction, is the reference's tangent_basis", "[friction]") {
    // Chapter 5's warm start applies the remembered friction impulses along the engine's
    // tangents; the friction pass accumulated them along step 2's. Different pairs would warm
    // start each step with friction turned the wrong way.
    const double s = std::sqrt(1.0 / 3.0);
    for (const Vector3& n : {Vector3{0, 0, 1}, Vector3{0, 0, -1}, Vector3{1, 0, 0}, Vector3{0, -1, 0}, Vector3{s, s, s},
                             normalized(Vector3{0.5, 0, std::sqrt(3.0) / 2}), normalized(Vector3{1e-9, 1, -1e-12})}) {
        CAPTURE(n.x, n.y, n.z);
        const auto engine = friction_tangents(n);
        const auto chapter = friction::tangent_basis(n);
        CHECK(engine[0] == chapter[0]);
        CHECK(engine[1] == chapter[1]);
    }
}

TEST_CASE("the friction model's warm start does not depend on chapter 5's warm_start", "[friction]") {
    // The solver warm starts a model with friction itself, along the model's tangents: a
    // chapter 5 warm_start that applied only the normal impulses, or nothing, changes nothing.
    static constexpr ContactSolverHooks ignored_warm_start = [] {
        ContactSolverHooks hooks = friction::hooks;
        hooks.warm_start = [](RigidBody&, RigidBody&, const Contact&, const ContactImpulses&) {};
        return hooks;
    }();
    const Scene scene = friction_scene("block-on-incline-sticks");
    World usual = world_of(scene);
    World other = make_world(scene, ResponseModel{"friction", nullptr, nullptr, &ignored_warm_start});
    for (int i = 0; i < 120; ++i) {
        usual.step();
        other.step();
    }
    CHECK(usual.contact_solver_report().warm_started_points > 0);
    CHECK(usual.bodies()[0].position == other.bodies()[0].position);
    CHECK(usual.bodies()[0].velocity == other.bodies()[0].velocity);
    CHECK(usual.bodies()[0].angular_velocity == other.bodies()[0].angular_velocity);
}

TEST_CASE("the stack of ten boxes with friction 0.5 rests for the whole minute", "[friction]") {
    const Scene scene = friction_scene("stack-of-10-boxes-with-friction");
    // A minute of ten boxes is some 20 times slower under the sanitizers: the dev build judges it.
    if (testing::under_sanitizers && testing::is_heavy(scene)) return;
    World world = world_of(scene);
    // The boxes rock a little while they settle into the slop; the minute is judged after that.
    const auto settle = static_cast<std::size_t>(std::lround(5.0 / scene.settings.time_step));
    for (std::size_t i = 0; i < settle; ++i) world.step();
    std::vector<Vector3> settled;
    for (const RigidBody& body : world.bodies()) settled.push_back(body.position);
    for (std::size_t i = settle; i < steps_of(scene); ++i) world.step();
    double moved = 0.0;
    for (std::size_t b = 0; b < settled.size(); ++b) moved = std::max(moved, length(world.bodies()[b].position - settled[b]));
    CHECK(moved <= 1e-3);
    world.detect();
    CHECK(world.probes().penetration_max <= scene.settings.position_correction.slop * (1 + 1e-9));
}

namespace {

/// `count` cubes of 10 cm and 1 kg, friction 0.5, stacked touching on the ground (z up), on the
/// solver's defaults: the stack a game builds, ten times the height of a box's width and more.
World stack_of_cubes(int count, int shock_sweeps = ContactSolverSettings{}.shock_sweeps) {
    std::vector<RigidBody> bodies;
    for (int i = 0; i < count; ++i) {
        RigidBody box = make_box(1.0, {0.05, 0.05, 0.05}, {0, 0, 0.05 + 0.1 * i});
        box.restitution = 0.0;
        box.friction = box.static_friction = 0.5;
        bodies.push_back(box);
    }
    RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    ground.restitution = 0.0;
    ground.friction = ground.static_friction = 0.5;
    bodies.push_back(ground);
    WorldSettings settings{1.0 / 60, {0, 0, -g}};
    settings.position_correction = {0.5, 0.002};
    settings.contact_solver.shock_sweeps = shock_sweeps;
    return World(std::move(bodies), settings, *find_response_model("friction"));
}

}  // namespace

TEST_CASE("a stack of thirty boxes with friction stands on the default passes", "[friction]") {
    // The passes alone leave each box a little turning (100 passes do not carry the weight of
    // thirty boxes down exactly, and a face's four points share the spin), and the stack fell
    // over at about 2.6 s. The sweep, from the bottom up, solves each box against the one
    // below it held still, normal and friction to the passes' tolerance.
    World world = stack_of_cubes(30);
    std::vector<Vector3> start;
    for (const RigidBody& body : world.bodies()) start.push_back(body.position);
    for (int i = 0; i < 6 * 60; ++i) world.step();
    double moved = 0.0;
    for (std::size_t b = 0; b < start.size(); ++b) moved = std::max(moved, length(world.bodies()[b].position - start[b]));
    // Each box rests at the slop on the one below (2 mm), with the slop's share still being
    // pushed out: the top sinks by at most 30 slops and nothing moves sideways.
    CHECK(moved <= 30 * 0.002);
    for (const RigidBody& body : world.bodies()) {
        CHECK(std::hypot(body.position.x, body.position.y) <= 1e-6);
        CHECK(length(body.velocity) == 0.0);  // asleep
    }
    world.detect();
    CHECK(world.probes().penetration_max <= 0.002 * (1 + 1e-9));

    // The passes alone (chapter 5's page says so): within three seconds the top box is down.
    World without_sweep = stack_of_cubes(30, 0);
    for (int i = 0; i < 3 * 60; ++i) without_sweep.step();
    CHECK(without_sweep.bodies()[29].position.z < 1.0);
}

TEST_CASE("a speculative point's target is no bounce: without a bounce the passes run one phase", "[friction]") {
    // A box resting on the ground, and one 5 mm into it moving up at 1 m/s. The move takes
    // the upper box 0.84 m/s x dt = 14 mm up, so detection finds the pair 9 mm apart, within
    // the speculative distance: a point with a gap, whose target (approach no faster than
    // the gap closes in a step) is positive, 0.84 - 0.009 / dt = 0.30 m/s, as the pair
    // separates faster than that. It is no bounce (e = 0): with one pass allowed, friction's
    // phase alone runs, not the bounce's after it.
    std::vector<RigidBody> bodies{make_box(1.0, {0.05, 0.05, 0.05}, {0, 0, 0.05}),
                                  make_box(1.0, {0.05, 0.05, 0.05}, {0, 0, 0.145}, {}, {0, 0, 1.0}),
                                  make_immovable_plane({0, 0, 1}, {0, 0, 0})};
    for (RigidBody& body : bodies) {
        body.restitution = 0.0;
        body.friction = body.static_friction = 0.5;
    }
    WorldSettings settings{1.0 / 60, {0, 0, -g}};
    settings.contact_solver.velocity_iterations = 1;
    World world(std::move(bodies), settings, *find_response_model("friction"));
    world.step();
    REQUIRE(world.contacts().size() == 2);
    CHECK(world.contact_solver_report().velocity_passes == 1);
}
