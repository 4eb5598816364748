// The world's stepping: semi-implicit Euler against its closed form, the four stages on
// their own, and how a response model plugs in. The responders here are local test doubles
// with effects simple enough to predict exactly; no chapter code is linked.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_floating_point.hpp>

#include <algorithm>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "checks.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using workbook::engine_tests::is_close_to;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Takes all kinetic energy out of a pair: the response energy change is then minus the
/// pair's kinetic energy, a number the test knows in advance.
void stop_both(RigidBody& body1, RigidBody& body2, const Contact&) {
    body1.velocity = {};
    body2.velocity = {};
}

/// Kicks body 1 by one unit along the contact normal, which shows which body the world
/// passed as body 1 and which way the normal pointed.
void kick_body1_along_normal(RigidBody& body1, RigidBody&, const Contact& contact) { body1.velocity += contact.normal; }

/// Moves body 1 out along the normal by the knobs' share of the penetration (a one-sided projection).
void push_body1_out(RigidBody& body1, RigidBody&, const Contact& contact, const PositionCorrection& knobs) {
    body1.position += contact.normal * (knobs.fraction * (contact.penetration - knobs.slop));
}

const ResponseModel no_response{"none", nullptr, nullptr};
const ResponseModel stopping{"stop both", stop_both, nullptr};
const ResponseModel kick_and_push{"kick and push", kick_body1_along_normal, push_body1_out};

}  // namespace

TEST_CASE("free fall: v = g n dt and x = x0 + g dt^2 n (n + 1) / 2 after n steps, exactly", "[world][integrate]") {
    // dt and g are powers of two and the positions stay below 2^7, so semi-implicit Euler
    // is exact in double precision here and the closed form must match bit for bit.
    const double dt = 1.0 / 256.0;
    const Vector3 g{0.0, -8.0, 0.0};
    const Vector3 x0{1.0, 100.0, -2.0};
    World world({make_sphere(1.0, 0.5, x0)}, WorldSettings{dt, g}, no_response);

    for (int n = 1; n <= 1000; ++n) {
        world.step();
        const RigidBody& ball = world.bodies()[0];
        const double steps = n;
        if (ball.velocity != g * (steps * dt) || ball.position != x0 + g * (dt * dt * steps * (steps + 1) / 2)) {
            CAPTURE(n, ball.velocity, ball.position);
            FAIL("semi-implicit Euler left its closed form");
        }
    }
    CHECK(world.time() == 1000.0 / 256.0);
    CHECK(world.bodies()[0].velocity == Vector3{0.0, -31.25, 0.0});
    CHECK(world.bodies()[0].position == Vector3{1.0, 100.0 - 1000.0 * 1001.0 / 16384.0, -2.0});
}

TEST_CASE("explicit Euler free fall: x = x0 + g dt^2 n (n - 1) / 2, one step behind, exactly", "[world][integrate]") {
    // Same exact arithmetic as above; explicit Euler moves with the old velocity, so the
    // position lags the semi-implicit one by exactly g dt^2 n.
    const double dt = 1.0 / 256.0;
    const Vector3 g{0.0, -8.0, 0.0};
    const Vector3 x0{1.0, 100.0, -2.0};
    World world({make_sphere(1.0, 0.5, x0)}, WorldSettings{dt, g, Integrator::explicit_euler}, no_response);
    for (int n = 1; n <= 1000; ++n) {
        world.step();
        const RigidBody& ball = world.bodies()[0];
        const double steps = n;
        if (ball.velocity != g * (steps * dt) || ball.position != x0 + g * (dt * dt * steps * (steps - 1) / 2)) {
            CAPTURE(n, ball.velocity, ball.position);
            FAIL("explicit Euler left its closed form");
        }
    }
}

TEST_CASE("free fall under Earth gravity matches the closed form to rounding", "[world][integrate]") {
    const double dt = 1.0 / 240.0;
    const Vector3 g{0.0, -9.81, 0.0};
    const Vector3 x0{0.0, 10.0, 0.0};
    const Vector3 v0{1.5, 2.0, 0.0};
    World world({make_sphere(2.0, 0.5, x0, v0)}, WorldSettings{dt, g}, no_response);

    const int n = 240;
    for (int i = 0; i < n; ++i) world.step();
    const double steps = n;
    const RigidBody& ball = world.bodies()[0];
    // n additions, each rounding by at most an ulp of the running sum (below 16).
    CHECK_THAT(ball.velocity, is_close_to(v0 + g * (steps * dt), n * 16 * eps));
    CHECK_THAT(ball.position, is_close_to(x0 + v0 * (steps * dt) + g * (dt * dt * steps * (steps + 1) / 2), n * 16 * eps));
    CHECK_THAT(world.time(), WithinAbs(1.0, n * eps));
}

TEST_CASE("immovable bodies do not fall and do not move", "[world][integrate]") {
    RigidBody ground = make_immovable_plane({0, 1, 0}, {0, -5, 0});
    World world({ground, make_immovable_sphere(1.0, {3, 3, 3})}, WorldSettings{0.01, {0, -9.81, 0}}, no_response);
    for (int i = 0; i < 100; ++i) world.step();
    CHECK(world.bodies()[0].position == Vector3{0, -5, 0});
    CHECK(world.bodies()[0].velocity == Vector3{});
    CHECK(world.bodies()[1].position == Vector3{3, 3, 3});
    CHECK(world.contacts().empty());  // two immovable bodies are never paired
}

TEST_CASE("a kinematic body (immovable, with a velocity) keeps its velocity and moves at it", "[world][integrate]") {
    // A moving platform: gravity does not pull it, and a ball landing on it does not slow it.
    RigidBody platform = make_immovable_plane({0, 1, 0}, {0, 0, 0});
    platform.velocity = {1.5, 0, 0};
    const ResponseModel stick{"stick", [](RigidBody& a, RigidBody& b, const Contact&) {
                                  RigidBody& mover = a.is_immovable() ? b : a;
                                  mover.velocity = (a.is_immovable() ? a : b).velocity;
                              }, nullptr};
    World world({platform, make_sphere(1.0, 0.5, {0, 0.6, 0})}, WorldSettings{0.01, {0, -9.81, 0}}, stick);
    for (int i = 0; i < 100; ++i) world.step();
    CHECK(world.bodies()[0].velocity == Vector3{1.5, 0, 0});
    CHECK_THAT(world.bodies()[0].position, is_close_to(Vector3{1.5, 0, 0}, 100 * 4 * eps));
    CHECK(world.bodies()[1].velocity.x == 1.5);  // the ball rides along
}

TEST_CASE("a spinning body turns by |omega| t and its world inverse inertia follows", "[world][integrate]") {
    RigidBody box;
    box.inverse_mass = 1.0 / 12.0;
    box.inertia_body = solid_box_inertia(12.0, {1, 2, 3});  // diag(52, 40, 20)
    box.shape = Shape::box({1, 2, 3});
    // A quarter turn about z in 90 steps of 1/180 s.
    box.angular_velocity = {0, 0, std::numbers::pi};
    World world({box}, WorldSettings{1.0 / 180.0, {}}, no_response);
    for (int i = 0; i < 90; ++i) world.integrate();

    const RigidBody& turned = world.bodies()[0];
    CHECK_THAT(turned.orientation, is_close_to(from_axis_angle({0, 0, 1}, std::numbers::pi / 2), 90 * 4 * eps));
    CHECK_THAT(turned.inverse_inertia_world, is_close_to(Matrix3::diagonal({1.0 / 40, 1.0 / 52, 1.0 / 20}), 1e-15));
}

TEST_CASE("step() is integrate, detect, respond, correct in that order", "[world][stages]") {
    const std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, 0, 0}), make_sphere(1.0, 0.5, {0, 0.45, 0}),
                                        make_sphere(2.0, 0.5, {0.9, 0.5, 0}, {-1, 0, 0})};
    const WorldSettings settings{0.01, {0, -9.81, 0}};
    World stepped(bodies, settings, kick_and_push);
    World staged(bodies, settings, kick_and_push);

    for (int i = 0; i < 5; ++i) {
        stepped.step();
        staged.integrate();
        staged.detect();
        staged.respond();
        staged.correct();
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        CAPTURE(i);
        CHECK(staged.bodies()[i].position == stepped.bodies()[i].position);
        CHECK(staged.bodies()[i].velocity == stepped.bodies()[i].velocity);
    }
    CHECK(staged.contacts().size() == stepped.contacts().size());
    // Only step() advances the clock; the stages on their own are timing-free.
    CHECK(stepped.time() == 5 * 0.01);
    CHECK(staged.time() == 0.0);
}

TEST_CASE("under event timing step() is integrate_impact_to_impact, detect, respond, correct, keep_answered_impacts",
          "[world][stages][event]") {
    // A ball falling onto the ground and another rolling into a resting one: impacts within a
    // step, and a resting contact for the back-stop.
    const std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, 0, 0}), make_sphere(1.0, 0.5, {0, 0.52, 0}, {0, -3, 0}),
                                        make_sphere(2.0, 0.5, {2.02, 0.5, 0}, {-4, 0, 0}), make_sphere(1.0, 0.5, {3.5, 0.5, 0})};
    WorldSettings settings{0.01, {0, -9.81, 0}};
    settings.contact_timing = ContactTiming::event;
    World stepped(bodies, settings, kick_and_push);
    World staged(bodies, settings, kick_and_push);

    std::size_t contacts = 0;
    for (int i = 0; i < 5; ++i) {
        stepped.step();
        contacts += stepped.contacts().size();
        staged.integrate_impact_to_impact();
        staged.detect();
        staged.respond();
        staged.correct();
        staged.keep_answered_impacts();
        REQUIRE(staged.contacts().size() == stepped.contacts().size());
        for (std::size_t c = 0; c < stepped.contacts().size(); ++c) {
            CHECK(staged.contacts()[c].body1 == stepped.contacts()[c].body1);
            CHECK(staged.contacts()[c].body2 == stepped.contacts()[c].body2);
        }
        CHECK(staged.probes().response_energy_change == stepped.probes().response_energy_change);
    }
    CHECK(contacts > 0);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        CAPTURE(i);
        CHECK(staged.bodies()[i].position == stepped.bodies()[i].position);
        CHECK(staged.bodies()[i].velocity == stepped.bodies()[i].velocity);
    }
}

TEST_CASE("under event timing a step after bodies() or a stage called on its own sees the bodies as they now are",
          "[world][stages][event]") {
    // An event-timed step leaves its copies of the bodies for the next one (EventScratch::
    // copies_known); a change made between steps must not be stepped past. Each world below
    // is compared with a new one built from the same bodies, which has no copies to reuse.
    std::vector<RigidBody> bodies{make_immovable_plane({0, 1, 0}, {0, 0, 0})};
    for (int n = 0; n < 16; ++n)
        bodies.push_back(make_sphere(1.0, 0.1, {0.25 * (n % 4), 0.12 + 0.21 * (n / 4), 0.05 * (n % 3)}, {0, -1.0 - 0.25 * n, 0}));
    WorldSettings settings{0.01, {0, -9.81, 0}};
    settings.contact_timing = ContactTiming::event;
    const auto same_as_new_world = [&](World& world) {
        // Read through a const World: the writable bodies() would clear the copies itself.
        const std::span<const RigidBody> now = std::as_const(world).bodies();
        World fresh(std::vector<RigidBody>(now.begin(), now.end()), settings, kick_and_push);
        for (int i = 0; i < 10; ++i) {
            world.step();
            fresh.step();
        }
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            CAPTURE(i);
            CHECK(std::as_const(world).bodies()[i].position == std::as_const(fresh).bodies()[i].position);
            CHECK(std::as_const(world).bodies()[i].velocity == std::as_const(fresh).bodies()[i].velocity);
        }
    };
    SECTION("a body's velocity, size and mass changed through bodies()") {
        World world(bodies, settings, kick_and_push);
        for (int i = 0; i < 5; ++i) world.step();
        world.bodies()[3].velocity = {0.5, 2.0, 0};
        world.bodies()[5].shape.radius = 0.12;
        world.bodies()[7].inverse_mass = 0.0;  // pinned where it is
        world.bodies()[7].velocity = {};
        same_as_new_world(world);
    }
    SECTION("the discrete step's integrate() called on its own between steps") {
        World world(bodies, settings, kick_and_push);
        for (int i = 0; i < 5; ++i) world.step();
        world.integrate();  // every body moves a step, without the event loop
        same_as_new_world(world);
    }
}

TEST_CASE("each stage does its own part and nothing more", "[world][stages]") {
    // A ball sunk 0.25 into the ground (index 0), falling at 1 m/s, no gravity.
    World world({make_immovable_plane({0, 1, 0}, {0, 0, 0}), make_sphere(1.0, 0.5, {0, 0.25, 0}, {0, -1, 0})},
                WorldSettings{0.125, {}}, kick_and_push);
    const RigidBody& ball = world.bodies()[1];

    world.integrate();
    CHECK(ball.position == Vector3{0, 0.125, 0});
    CHECK(world.contacts().empty());

    world.detect();
    REQUIRE(world.contacts().size() == 1);
    const Contact& contact = world.contacts()[0];
    CHECK(contact.body1 == 1);  // the sphere, although the plane comes first in the world
    CHECK(contact.body2 == 0);
    CHECK(contact.normal == Vector3{0, 1, 0});
    CHECK(contact.penetration == 0.375);
    CHECK(ball.velocity == Vector3{0, -1, 0});

    world.respond();
    CHECK(ball.velocity == Vector3{0, 0, 0});  // kicked by +normal
    CHECK(ball.position == Vector3{0, 0.125, 0});

    world.correct();
    CHECK(ball.position == Vector3{0, 0.5, 0});  // pushed out to rest on the plane
    CHECK(world.bodies()[0].position == Vector3{});
}

TEST_CASE("without a response model, contacts are found and velocities left alone", "[world][response]") {
    const Vector3 g{0, -9.81, 0};
    const double dt = 0.01;
    // Two overlapping, approaching balls on the ground: three contacts in all.
    World world({make_sphere(1.0, 0.5, {0, 0.4, 0}, {1, 0, 0}), make_sphere(2.0, 0.5, {0.8, 0.4, 0}, {-1, 0, 0}),
                 make_immovable_plane({0, 1, 0}, {0, 0, 0})},
                WorldSettings{dt, g}, no_response);
    world.step();
    CHECK(world.contacts().size() == 3);
    CHECK(world.bodies()[0].velocity == Vector3{1, 0, 0} + g * dt);
    CHECK(world.bodies()[1].velocity == Vector3{-1, 0, 0} + g * dt);
    CHECK(world.probes().response_energy_change == 0.0);
    CHECK(world.probes().contacts == 3);
    // The deepest of the three as detected: after one step the balls are 0.78 m apart and
    // overlap by 0.22 m; each is only about 0.1 m into the ground.
    double deepest = 0.0;
    for (const Contact& c : world.contacts()) deepest = std::max(deepest, c.penetration);
    CHECK(world.probes().penetration_max == deepest);
    CHECK_THAT(deepest, Catch::Matchers::WithinAbs(0.22, 1e-12));
}

TEST_CASE("the probes report the kinetic energy the responses changed", "[world][response]") {
    // Gravity off, so after integrate() the velocities are still the initial ones:
    // pair A (2 kg at 1 m/s, 1 kg at 2 m/s) holds 1 + 2 J, the ball on the ground 1/2 * 4 * 1 = 2 J.
    World world({make_sphere(2.0, 0.5, {0, 0, 0}, {1, 0, 0}), make_sphere(1.0, 0.5, {0.9, 0, 0}, {-2, 0, 0}),
                 make_immovable_plane({0, 1, 0}, {0, -10, 0}), make_sphere(4.0, 0.5, {5, -9.6, 0}, {0, -1, 0})},
                WorldSettings{1.0 / 1024.0, {}}, stopping);
    world.step();
    const Probes after_first = world.probes();
    CHECK(after_first.contacts == 2);
    CHECK(after_first.response_energy_change == -5.0);
    CHECK(after_first.kinetic() == 0.0);
    CHECK(after_first.time == 1.0 / 1024.0);

    // Still overlapping, but nothing left to take: the change is per step, not cumulative.
    world.step();
    CHECK(world.probes().contacts == 2);
    CHECK(world.probes().response_energy_change == 0.0);
}

TEST_CASE("the world refreshes each body's world inverse inertia when built", "[world]") {
    RigidBody ball = make_sphere(2.0, 0.5, {0, 0, 0});
    ball.inverse_inertia_world = Matrix3::zero();  // stale on purpose
    const World world({ball}, WorldSettings{}, no_response);
    CHECK_THAT(world.bodies()[0].inverse_inertia_world, is_close_to(Matrix3::diagonal({5, 5, 5}), 8 * eps));
    CHECK(world.model().name == "none");
    CHECK(world.settings().time_step == 1.0 / 240.0);
}

TEST_CASE("correct() hands the scene's position-correction knobs to the corrector", "[world][stages]") {
    // A ball 0.375 m into the ground; fraction 0.5 and slop 0.125 remove 0.5 (0.375 - 0.125) = 0.125 m.
    WorldSettings settings{0.01, {}};
    settings.position_correction = {0.5, 0.125};
    World world({make_immovable_plane({0, 1, 0}, {0, 0, 0}), make_sphere(1.0, 0.5, {0, 0.125, 0})}, settings, kick_and_push);
    world.detect();
    world.correct();
    CHECK(world.bodies()[1].position == Vector3{0, 0.25, 0});
}
