// The accuracy families of chapters 1, 2 and 4 (tools/accuracy/families.hpp), as value
// assertions, each with its chapter's model from the response model table: chapter 1's
// inelastic, chapter 1's inelastic with chapter 2's projection, chapter 4's angular-impulse.
// Chapter 3's families are in event_timing.cpp.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "families.hpp"
#include "models.hpp"

using namespace workbook;
using namespace workbook::accuracy;

namespace {

WorldSettings settings_for(double dt, Integrator integrator, ContactTiming timing) {
    WorldSettings s;
    s.time_step = dt;
    s.integrator = integrator;
    s.contact_timing = timing;
    return s;
}

WorldSettings event_settings(double dt) {
    return settings_for(dt, Integrator::exact_under_gravity, ContactTiming::event);
}

constexpr double steps[] = {1.0 / 30, 1.0 / 60, 1.0 / 240, 1.0 / 3840};

}  // namespace

TEST_CASE("chapter 1 family: the perfectly inelastic head-on pair", "[accuracy][chapter-families]") {
    HeadOn pair;
    pair.restitution = 0.0;
    // Closed form: both leave at the common velocity p / (m1 + m2) = (2 - 3) / 4 m/s.
    CHECK(std::abs(pair.v1_after() - -0.25) <= 1e-15);
    CHECK(std::abs(pair.v2_after() - -0.25) <= 1e-15);
    const ResponseModel& inelastic = chapter_model("inelastic");
    for (const double dt : steps) {
        INFO("dt = 1/" << 1.0 / dt);
        CHECK(head_on_error(event_settings(dt), inelastic, pair).error <= 1e-12);
    }
    SECTION("discrete timing: the velocities are exact, only the moment (so the positions) is late") {
        World world({make_sphere(pair.m1, pair.radius, {pair.x1(), 0, 0}, {pair.v1, 0, 0}),
                     make_sphere(pair.m2, pair.radius, {pair.x2(), 0, 0}, {pair.v2, 0, 0})},
                    settings_for(1.0 / 60, Integrator::semi_implicit_euler, ContactTiming::discrete), inelastic);
        for (int n = 0; n < 60; ++n) world.step();
        CHECK(std::abs(world.bodies()[0].velocity.x - -0.25) <= 1e-15);
        CHECK(std::abs(world.bodies()[1].velocity.x - -0.25) <= 1e-15);
        CHECK(head_on_error(world.settings(), inelastic, pair).error > 1e-2);
    }
}

TEST_CASE("chapter 2 family: a resting stack sinks as the square of the step", "[accuracy][chapter-families]") {
    const ResponseModel model = inelastic_with_projection();
    const auto sink = [&model](double dt, int balls) {
        return resting_stack_error(settings_for(dt, Integrator::semi_implicit_euler, ContactTiming::discrete), model, balls)
            .error;
    };
    // One ball: each step's fall (g dt^2) is removed in full by the one contact's projection.
    for (const double dt : steps) CHECK(sink(dt, 1) == 0.0);
    // Three: one pass cannot clear a column, and the stack settles where the passes balance the
    // pull, which grows as dt^2: four times finer steps sink 16 times less.
    const double coarse = sink(1.0 / 240, 3), fine = sink(1.0 / 960, 3);
    INFO("sink at 1/240 s: " << coarse << " r, at 1/960 s: " << fine << " r");
    CHECK(coarse > 0.0);
    CHECK(std::abs(coarse / fine - 16.0) <= 0.05 * 16.0);
    // Event timing adds nothing: nothing is on its way to a contact; the error is the correction's.
    CHECK(resting_stack_error(event_settings(1.0 / 240), model, 3).error ==
          resting_stack_error(settings_for(1.0 / 240, Integrator::exact_under_gravity, ContactTiming::discrete), model, 3)
              .error);
}

TEST_CASE("chapter 4 family: the tilted rod's closed form is the worked example's", "[accuracy][chapter-families]") {
    // A thin rod (t = 0): J = (1 + e) m u / (1 + 3 cos^2 theta), w' = 6 J cos(theta) / (m L).
    TiltedRod thin;
    thin.thickness = 0.0;
    const double c = std::cos(thin.tilt_degrees * std::numbers::pi / 180.0);
    const double j = (1.0 + thin.restitution) * thin.mass * thin.impact_speed / (1.0 + 3.0 * c * c);
    CHECK(std::abs(thin.impulse() - j) <= 1e-14 * j);
    CHECK(std::abs(thin.spin_after() - 6.0 * j * c / (thin.mass * thin.length)) <= 1e-14 * thin.spin_after());
    // The lower end rises at e u after the impact.
    CHECK(std::abs(thin.velocity_after() + thin.spin_after() * thin.lever() - thin.restitution * thin.impact_speed) <= 1e-14);
    // The bench's box is 5 cm thick: its edge is closer to the centre, so it takes more impulse.
    const TiltedRod box;
    CHECK(box.impulse() > thin.impulse());
    CHECK(std::abs(box.velocity_after() + box.spin_after() * box.lever() - box.restitution * box.impact_speed) <= 1e-14);
}

TEST_CASE("chapter 4 family: event timing lands the tilted rod at its time of impact, exact to rounding",
          "[accuracy][chapter-families][event]") {
    const ResponseModel& angular = chapter_model("angular-impulse");
    for (const double dt : steps) {
        INFO("dt = 1/" << 1.0 / dt);
        CHECK(tilted_rod_error(event_settings(dt), angular).error <= 1e-12);
        // Discrete timing finds the edge late, below the ground and faster than u.
        CHECK(tilted_rod_error(settings_for(dt, Integrator::exact_under_gravity, ContactTiming::discrete), angular).error >
              1e-5);
    }
}

TEST_CASE("chapter 4 family: a free box keeps L and E to rounding at every step, event timing included",
          "[accuracy][chapter-families]") {
    const ResponseModel& angular = chapter_model("angular-impulse");
    for (const double dt : steps) {
        INFO("dt = 1/" << 1.0 / dt);
        for (ContactTiming timing : {ContactTiming::discrete, ContactTiming::event})
            CHECK(torque_free_box_error(settings_for(dt, Integrator::exact_under_gravity, timing), angular).error <= 1e-12);
    }
    SECTION("event timing turns a free box as the discrete step does, precession included") {
        RigidBody box = make_box(1.0, {0.5, 0.25, 0.1}, {});
        box.angular_velocity = {0.01, 4.0, 0.01};
        World discrete({box}, settings_for(1.0 / 240, Integrator::exact_under_gravity, ContactTiming::discrete), angular);
        World event({box}, event_settings(1.0 / 240), angular);
        for (int n = 0; n < 2400; ++n) {
            discrete.step();
            event.step();
        }
        const Vector3 w = discrete.bodies()[0].angular_velocity;
        INFO("w after 10 s: discrete (" << w.x << ", " << w.y << ", " << w.z << ")");
        CHECK(length(event.bodies()[0].angular_velocity - w) <= 1e-12 * length(w));
        // The tennis racket: in the box's own frame the spin about its middle axis reverses at
        // least once in 10 s (turning about a fixed w, it never would).
        double lowest = box.angular_velocity.y;
        World again({box}, event_settings(1.0 / 240), angular);
        for (int n = 0; n < 2400; ++n) {
            again.step();
            const RigidBody& b = again.bodies()[0];
            lowest = std::min(lowest, rotate(conjugate(b.orientation), b.angular_velocity).y);
        }
        CHECK(lowest < -3.0);
    }
}
