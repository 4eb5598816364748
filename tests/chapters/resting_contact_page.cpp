// Ties chapter 5's page (chapters/resting-contact/chapter.md) and scenes to the code:
// 1. The worked example (two balls on the ground): every number it prints is recomputed here,
//    in closed form and with the reference solver run for one and for ten passes.
// 2. Every public step test is named under the heading of its own step.
// 3. The column of 15 balls and the stack of 10 boxes rest: once settled (5 s), no body moves
//    more than 1 mm over the rest of the scene, and no contact is deeper than the slop. Judged
//    in the dev build only: the sanitizer build runs these heavy scenes' first half second in
//    the motion and shortcut tests (sanitized_run.hpp), too short to settle.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "chapter_page.hpp"
#include "sanitized_run.hpp"
#include "resting-contact.hpp"
#include "workbook/probes.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "resting-contact"); }

constexpr int digits = 4;
/// The boxes rock a little while they settle into the slop; the test starts after that.
constexpr double settle_seconds = 5.0;

/// Two 1 kg balls standing on each other on the ground, run one step with `passes` velocity passes.
World two_balls(int passes) {
    std::vector<RigidBody> bodies{make_sphere(1.0, 0.05, {0, 0, 0.05}), make_sphere(1.0, 0.05, {0, 0, 0.1499}),
                                  make_immovable_plane({0, 0, 1}, {0, 0, 0})};
    WorldSettings settings{1.0 / 60, {0, 0, -9.81}};
    settings.contact_solver.velocity_iterations = passes;
    settings.contact_solver.warm_start = false;
    // The passes alone, as the page works them: a shock sweep would stop the upper ball on
    // the lower whatever the passes left.
    settings.contact_solver.shock_sweeps = 0;
    const ResponseModel model{"resting-contact", nullptr, nullptr, &resting_contact::hooks};
    World world(std::move(bodies), settings, model);
    world.step();
    return world;
}

}  // namespace

TEST_CASE("chapter 5 worked example: one pass halves the impulses of a two-ball stack", "[resting-contact]") {
    const double m = 1.0, g = 9.81, dt = 1.0 / 60;
    const double s = g * dt;
    const World one = two_balls(1);
    // The ground's contact is the first in the solver's order, the balls' contact the second.
    std::vector<double> impulses;
    for (const ContactImpulses& c : one.contact_solver().impulses()) impulses.push_back(c.points[0].normal);
    std::sort(impulses.begin(), impulses.end());
    REQUIRE(impulses.size() == 2);
    CHECK(std::abs(impulses[1] - m * s) <= 1e-15);
    CHECK(std::abs(impulses[0] - m * s / 2) <= 1e-15);
    for (int b = 0; b < 2; ++b) CHECK(std::abs(one.bodies()[static_cast<std::size_t>(b)].velocity.z + s / 2) <= 1e-15);
    const World ten = two_balls(10);
    for (int b = 0; b < 2; ++b) CHECK(std::abs(ten.bodies()[static_cast<std::size_t>(b)].velocity.z + s / 1024) <= 1e-15);

    check_worked_example(chapter_page(),
                         {.anchor = "{#resting_contact_worked_example}",
                          .formulas = {page_quantity(m, "kg", digits), page_quantity(g, "m/s^2", digits),
                                       page_quantity(s, "m/s", digits), page_quantity(m * s, "N\\,s", digits),
                                       page_quantity(m * s / 2, "N\\,s", digits), page_quantity(-s / 2, "m/s", digits),
                                       page_quantity(2 * m * s, "N\\,s", digits), page_quantity(s / 1024, "m/s", digits)},
                          .symbolic_text = {"1/60\\,\\mathrm{s}", "s/1024", "m/2", "s/2", "2 m s"},
                          .symbolic_patterns = {}});
}

TEST_CASE("chapter 5: every public step test is named under its step", "[resting-contact]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/resting_contact.cpp");
    CHECK(found == 10);
}

namespace {

/// Once settled (settle_seconds), no body of the scene moves more than 1 mm over the rest of
/// it, and no contact is deeper than the slop. Heavy: judged in the dev build only.
void check_rests(const char* name) {
    CAPTURE(name);
    const Scene scene = load_scene(std::string(WORKBOOK_SOURCE_DIR) + "/chapters/resting-contact/scenes/" + name + ".json");
    if (under_sanitizers && is_heavy(scene)) return;  // the dev build's run judges it
    World world = make_world(scene, *find_response_model(scene.responder));
    const std::size_t steps = step_count(scene.duration, scene.settings.time_step);
    const std::size_t settle = static_cast<std::size_t>(std::lround(settle_seconds / scene.settings.time_step));
    for (std::size_t i = 0; i < settle; ++i) world.step();
    std::vector<Vector3> settled;
    for (const RigidBody& body : world.bodies()) settled.push_back(body.position);
    for (std::size_t i = settle; i < steps; ++i) world.step();
    double moved = 0.0;
    for (std::size_t b = 0; b < settled.size(); ++b) moved = std::max(moved, length(world.bodies()[b].position - settled[b]));
    CHECK(moved <= 1e-3);
    world.detect();
    // To a nanometre: the position pass halves what lies beyond the slop every step, and a
    // column that falls asleep (workbook/sleeping.hpp) keeps the last step's remainder
    // (6e-11 m for the column of balls).
    CHECK(world.probes().penetration_max <= scene.settings.position_correction.slop + 1e-9);
}

}  // namespace

TEST_CASE("chapter 5 scenes: the column of balls rests", "[resting-contact]") { check_rests("column-of-15-balls"); }

// The frictionless stack of ten boxes stands: every normal is vertical, so nothing pushes a box
// sideways, and the page and the caption say so. Judged as the column of balls (check_rests:
// settled after 5 s, then no box moves more than 1 mm and no contact is deeper than the slop),
// and closer: the boxes are built touching and held from the first step, so no box moves or
// tilts by more than the solver's tolerance lets it drift over the minute. The passes stop when
// no point's velocity changes by more than settings.tolerance (1e-9 m/s): a velocity that
// should be 0 is within that of it, a position drifts by at most that times the duration, and a
// box turns by at most that over its half width times the duration (measured: 2.6e-9 m and
// 1.7e-9 rad). A box the detection left on three of its four corners would turn off the stack.
TEST_CASE("chapter 5 scenes: the frictionless stack of ten boxes rests the whole minute", "[resting-contact]") {
    check_rests("stack-of-10-boxes");
    const Scene scene = load_scene(std::string(WORKBOOK_SOURCE_DIR) + "/chapters/resting-contact/scenes/stack-of-10-boxes.json");
    if (under_sanitizers && is_heavy(scene)) return;  // the dev build's run judges it
    World world = make_world(scene, *find_response_model(scene.responder));
    std::vector<Vector3> start;
    for (const RigidBody& body : world.bodies()) start.push_back(body.position);
    double moved = 0.0;  // the largest distance of a box from where it started, over every step
    double tilt = 0.0;   // the largest angle of a box's vertical axis from the vertical
    for (std::size_t i = 0; i < step_count(scene.duration, scene.settings.time_step); ++i) {
        world.step();
        for (std::size_t b = 0; b < start.size(); ++b) {
            const RigidBody& body = world.bodies()[b];
            moved = std::max(moved, length(body.position - start[b]));
            const Vector3 up = rotate(body.orientation, Vector3{0, 0, 1});
            tilt = std::max(tilt, std::atan2(std::hypot(up.x, up.y), up.z));
        }
    }
    const double drift = scene.settings.contact_solver.tolerance * scene.duration;  // m
    const double half_width = world.bodies()[0].shape.half_extents.x;               // m, every box's
    CHECK(moved <= drift);
    CHECK(tilt <= drift / half_width);
}
