// A NaN or an infinity left by a stage stops the run at once, and the error says which body,
// which quantity, which step and which stage; with the guard off (benchmarks) it does not.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <limits>
#include <string>
#include <vector>

#include "workbook/guards.hpp"
#include "workbook/scene.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using Catch::Matchers::ContainsSubstring;

namespace {

/// A broken responder: divides by a zero it should have guarded against.
void nan_responder(RigidBody& body1, RigidBody& /*body2*/, const Contact& /*contact*/) {
    body1.velocity.x = std::numeric_limits<double>::quiet_NaN();
}

/// Two balls that touch on the third step at dt = 0.1: 1 m apart (surfaces), closing at 4 m/s.
std::vector<RigidBody> closing_pair() {
    return {make_sphere(1.0, 0.5, {0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}),
            make_sphere(1.0, 0.5, {2.0, 0.0, 0.0}, {-2.0, 0.0, 0.0})};
}

}  // namespace

TEST_CASE("a stage that leaves a NaN stops the world with body, quantity, step and stage", "[guards]") {
    WorldSettings settings;
    settings.time_step = 0.1;
    World world(closing_pair(), settings, ResponseModel{"nan", &nan_responder, nullptr});
    world.name_bodies({"left", "right"});
    world.step();
    world.step();
    try {
        world.step();
        FAIL("no NonFiniteState was thrown");
    } catch (const NonFiniteState& error) {
        CHECK(error.body() == 0);
        CHECK(error.body_name() == "left");
        CHECK(error.quantity() == "velocity");
        CHECK(error.step() == 3);
        CHECK(error.stage() == "respond");
        CHECK_THAT(std::string(error.what()),
                   ContainsSubstring("step 3, stage respond: body 0 (\"left\"): velocity is not finite: (nan"));
    }
}

TEST_CASE("an overflow in integrate is reported as the position of that body", "[guards]") {
    WorldSettings settings;
    settings.time_step = 1.0;
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.5, {0.0, 0.0, 0.0}),
                                  make_sphere(1.0, 0.5, {1.7e308, 0.0, 0.0}, {1.7e308, 0.0, 0.0})};
    World world(bodies, settings, ResponseModel{"none", nullptr, nullptr});
    try {
        world.step();
        FAIL("no NonFiniteState was thrown");
    } catch (const NonFiniteState& error) {
        CHECK(error.body() == 1);
        CHECK(error.body_name().empty());
        CHECK(error.quantity() == "position");
        CHECK(error.step() == 1);
        CHECK(error.stage() == "integrate");
        CHECK_THAT(std::string(error.what()), ContainsSubstring("body 1: position is not finite: (inf, 0, 0)"));
    }
}

TEST_CASE("under event timing an overflow while moving to the end of the step is reported as that body's position",
          "[guards][event]") {
    // The event-timed step checks the bodies in the same pass that moves them to the end of
    // the step (as the discrete integrate() does), not in a pass of its own: it must still say
    // which body and what.
    WorldSettings settings;
    settings.time_step = 1.0;
    settings.contact_timing = ContactTiming::event;
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.5, {0.0, 0.0, 0.0}),
                                  make_sphere(1.0, 0.5, {1.7e308, 0.0, 0.0}, {1.7e308, 0.0, 0.0})};
    World world(bodies, settings, ResponseModel{"nan", &nan_responder, nullptr});
    try {
        world.step();
        FAIL("no NonFiniteState was thrown");
    } catch (const NonFiniteState& error) {
        CHECK(error.body() == 1);
        CHECK(error.quantity() == "position");
        CHECK(error.step() == 1);
        CHECK(error.stage() == "event: advance");
        CHECK_THAT(std::string(error.what()), ContainsSubstring("body 1: position is not finite: (inf, 0, 0)"));
    }
}

TEST_CASE("under event timing a responder that leaves a NaN at an impact is reported at that impact", "[guards][event]") {
    WorldSettings settings;
    settings.time_step = 0.1;
    settings.contact_timing = ContactTiming::event;
    World world(closing_pair(), settings, ResponseModel{"nan", &nan_responder, nullptr});
    world.step();
    world.step();
    try {
        world.step();  // the balls touch 0.05 s into the third step
        FAIL("no NonFiniteState was thrown");
    } catch (const NonFiniteState& error) {
        CHECK(error.body() == 0);
        CHECK(error.quantity() == "velocity");
        CHECK(error.step() == 3);
        CHECK(error.stage() == "event: respond");
    }
}

TEST_CASE("the guard is on by default and can be turned off for benchmarks", "[guards]") {
    CHECK(WorldSettings{}.check_finite);
    WorldSettings settings;
    settings.time_step = 0.1;
    settings.check_finite = false;
    World world(closing_pair(), settings, ResponseModel{"nan", &nan_responder, nullptr});
    for (int i = 0; i < 3; ++i) world.step();
    CHECK(std::isnan(world.bodies()[0].velocity.x));
}

TEST_CASE("scene files give their body names to the guard", "[guards][scene]") {
    const Scene scene = parse_scene(R"({"title": "t", "responder": "x", "time_step": 0.1, "duration": 1,
        "bodies": [{"name": "cart", "shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "velocity": [2, 0, 0]},
                   {"shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": [2, 0, 0], "velocity": [-2, 0, 0]}]})",
                                    "names.json");
    World world = make_world(scene, ResponseModel{"nan", &nan_responder, nullptr});
    REQUIRE(world.body_names().size() == 2);
    CHECK(world.body_names()[0] == "cart");
    CHECK_THROWS_WITH(([&world] { for (int i = 0; i < 3; ++i) world.step(); })(),
                      ContainsSubstring("body 0 (\"cart\"): velocity"));
}
