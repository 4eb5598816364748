// Ties chapter 6's page (chapters/friction/chapter.md) to the code:
// 1. The energy pitfall's worked example: a rod landing on its end with e = 1 and friction
//    0.5 leaves with more kinetic energy than it brought when Newton's restitution is solved
//    together with friction, and with less in the world's two phases; every number the page
//    prints is recomputed here, with the reference's own functions.
// 2. The rolling ball's worked example: the closed forms the page prints.
// 3. The figures' captions: each number recomputed.
// 4. Every public step test is named under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "chapter_page.hpp"
#include "friction.hpp"
#include "resting-contact.hpp"
#include "workbook/contact_solver.hpp"
#include "workbook/probes.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "friction"); }

constexpr int digits = 4;
constexpr double g = 9.81;

/// The page's rod: 1 kg, 1 m long and 10 cm thick, tilted 45 degrees about y so that its end
/// at +x is lowest, falling at 2 m/s and drifting at 1 m/s towards -x, without spin; e = 1
/// and friction 0.5 on the rod and the ground. One contact at that end, normal +z.
struct Rod {
    std::vector<RigidBody> bodies;
    Contact contact;
};

Rod landing_rod() {
    const double angle = std::numbers::pi / 4;
    RigidBody rod = make_box(1.0, {0.5, 0.05, 0.05}, {0, 0, 0.5 * std::sin(angle)},
                             from_axis_angle({0, 1, 0}, angle), {-1.0, 0, -2.0});
    RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    for (RigidBody* body : {&rod, &ground}) {
        body->restitution = 1.0;
        body->friction = body->static_friction = 0.5;
    }
    Rod result{{rod, ground}, {}};
    result.contact.body1 = 0;
    result.contact.body2 = 1;
    result.contact.normal = {0, 0, 1};
    result.contact.add_point(rod.position + Vector3{0.5 * std::cos(angle), 0, -0.5 * std::sin(angle)}, 0.0);
    return result;
}

/// Newton's restitution solved together with friction: chapter 5's normal pass aiming at the
/// bounce and this chapter's friction pass, in turn, until nothing changes.
double kinetic_energy_solved_together(Rod rod) {
    ContactImpulses impulses;
    resting_contact::prepare(rod.bodies[0], rod.bodies[1], rod.contact, impulses, ContactSolverSettings{}, {}, 1.0 / 60);
    for (int pass = 0; pass < 1000; ++pass) {
        const double normal = resting_contact::solve_velocity(rod.bodies[0], rod.bodies[1], rod.contact, impulses);
        const double tangent = friction::solve_friction(rod.bodies[0], rod.bodies[1], rod.contact, impulses);
        if (normal <= 1e-15 && tangent <= 1e-15) break;
    }
    return kinetic_energy(rod.bodies[0]);
}

/// The world's contact solver: the approach stopped with friction, then the bounce alone.
double kinetic_energy_in_two_phases(Rod rod) {
    ContactSolverSettings settings;
    settings.warm_start = false;
    settings.tolerance = 1e-15;
    settings.velocity_iterations = 1000;
    ContactSolver solver;
    const std::vector<Contact> contacts{rod.contact};
    (void)solver.solve(rod.bodies, contacts, friction::hooks, settings, {}, 1.0 / 60, {0, 0, 1});
    return kinetic_energy(rod.bodies[0]);
}

}  // namespace

TEST_CASE("chapter 6 worked example: Newton's restitution with friction gives a landing rod energy; two phases do not",
          "[friction]") {
    const Rod rod = landing_rod();
    const double before = kinetic_energy(rod.bodies[0]);
    const double together = kinetic_energy_solved_together(rod);
    const double apart = kinetic_energy_in_two_phases(rod);
    CHECK(std::abs(before - 2.5) <= 1e-15);
    CHECK(together > before * 1.1);
    CHECK(apart < before);
    // The end's speeds before: straight down at 2 m/s along the normal, 1 m/s along -x.
    check_worked_example(chapter_page(),
                         {.anchor = "{#friction_energy_example}",
                          .formulas = {page_quantity(1.0, "kg", digits), page_quantity(1.0, "m/s", digits),
                                       page_quantity(1.0, "m", digits), page_quantity(10.0, "cm", digits),
                                       page_quantity(2.0, "m/s", digits), page_quantity(before, "J", digits),
                                       page_quantity(together, "J", digits), page_quantity(apart, "J", digits),
                                       page_number(100 * (together / before - 1), 2) + "\\,\\%"},
                          .symbolic_text = {"45^\\circ", "e = 1", "\\mu = 0.5"},
                          .symbolic_patterns = {}});
}

TEST_CASE("chapter 6 worked example: the ball that starts to roll", "[friction]") {
    const double v0 = 3.5, mu = 0.2, r = 0.1;
    const Scene scene = load_scene(std::string(WORKBOOK_SOURCE_DIR) + "/chapters/friction/scenes/ball-starts-rolling.json");
    World world = make_world(scene, *find_response_model(scene.responder));
    for (std::size_t i = 0; i < step_count(scene.duration, scene.settings.time_step); ++i) world.step();
    const double simulated = world.bodies()[0].velocity.x;
    const double t = 2 * v0 / (7 * mu * g);
    const double rolling = 5.0 / 7.0 * v0;
    // The slip v - w r falls at mu g + mu g m r^2 / I = 7/2 mu g; the speed at mu g.
    CHECK(std::abs(v0 - mu * g * t - rolling) <= 1e-15);
    CHECK(std::abs(2.5 * mu * g * t * r / r - rolling) <= 1e-15);
    check_worked_example(chapter_page(),
                         {.anchor = "{#friction_worked_example}",
                          .formulas = {page_quantity(v0, "m/s", digits), page_quantity(mu * g, "m/s^2", digits),
                                       page_quantity(t, "s", digits), page_quantity(rolling, "m/s", digits),
                                       page_quantity(2.5 * mu * g / r, "rad/s^2", digits),
                                       page_quantity(rolling / r, "rad/s", digits), page_quantity(1.0, "kg", digits),
                                       page_quantity(simulated, "m/s", digits)},
                          .symbolic_text = {"\\mu = 0.2", "g = 9.81", "r = 0.1", "\\tfrac25", "\\tfrac52", "\\tfrac72",
                                            "\\tfrac57", "\\tfrac75", "2 v_0", "7 \\mu g", "m r^2", "v_0"},
                          .symbolic_patterns = {}});
}

TEST_CASE("chapter 6: two thousand random landings of the rod never gain kinetic energy in the solver's two phases",
          "[friction]") {
    std::mt19937_64 random(20261125);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int sample = 0; sample < 2000; ++sample) {
        Rod rod = landing_rod();
        const double angle = (0.05 + 0.45 * unit(random)) * std::numbers::pi;
        const double vx = 4 * unit(random) - 2;
        const double vz = -0.6 - 2.4 * unit(random);
        const double spin = 20 * unit(random) - 10;
        const double e = unit(random);
        const double mu = 2 * unit(random);
        RigidBody& body = rod.bodies[0];
        body.orientation = from_axis_angle({0, 1, 0}, angle);
        body.update_world_inertia();
        body.velocity = {vx, 0, vz};
        body.angular_velocity = {0, spin, 0};
        body.restitution = e;
        body.friction = body.static_friction = mu;
        rod.bodies[1].friction = rod.bodies[1].static_friction = mu;
        rod.contact.points[0].position = body.position + Vector3{0.5 * std::cos(angle), 0, -0.5 * std::sin(angle)};
        const double before = kinetic_energy(body);
        const double after = kinetic_energy_in_two_phases(rod);
        worst = std::max(worst, after / before);
    }
    CHECK(worst <= 1.0 + 1e-12);
}

TEST_CASE("chapter 6: the figures' captions", "[friction]") {
    const ChapterPage page = chapter_page();
    const double theta = std::numbers::pi / 6;
    auto has = [&](const char* figure, const std::string& number) {
        CAPTURE(figure, number);
        CHECK(figure_caption(page, figure).find(number) != std::string::npos);
    };
    has("friction/block-on-incline-sticks", page_number(std::tan(theta), 3));
    has("friction/block-on-incline-slides", page_number(g * (std::sin(theta) - 0.3 * std::cos(theta)), 4));
    has("friction/box-sliding-to-rest", page_number(3.0 / (0.5 * g), 3) + " s");
    has("friction/box-sliding-to-rest", page_number(9.0 / (2 * 0.5 * g), 3) + " m");
    has("friction/ball-starts-rolling", page_number(2 * 3.5 / (7 * 0.2 * g), 2) + " s");
    has("friction/ball-starts-rolling", page_number(5.0 / 7 * 3.5, 2) + " m/s");
    has("friction/ball-with-backspin", page_number(2 * (2.0 + 0.1 * 60) / (7 * 0.2 * g), 4) + " s");
    CHECK(std::abs((5 * 2.0 - 2 * 0.1 * 60) / 7 - (-2.0 / 7)) <= 1e-15);
}

TEST_CASE("chapter 6: every public step test is named under its step", "[friction]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/friction.cpp");
    CHECK(found == 13);
}
