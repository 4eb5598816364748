// Ties the text of chapter 4 (chapters/angular-impulse/chapter.md) to the code.
//
// 1. The worked example (the tilted rod): every number it prints is recomputed here, in closed
//    form and with the reference responder, formatted as the page prints it and looked up in
//    the page; once the checked formulas are removed, no digit may be left in the section.
// 2. The exercise: every public step test of tests/steps/angular_impulse.cpp is named in the
//    page, under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "angular-impulse.hpp"
#include "chapter_page.hpp"
#include "workbook/contact.hpp"
#include "workbook/probes.hpp"
#include "workbook/rigid_body.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "angular-impulse"); }

/// This page prints its numbers to four significant digits: the rod's cosines are irrational.
constexpr int digits = 4;

}  // namespace

TEST_CASE("chapter 4 worked example: every number of the tilted rod is the physics", "[angular-impulse]") {
    const double m = 2.0, length_ = 1.0, degrees = 30.0, u = 3.0, e = 0.5;
    const double theta = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(theta);

    // Closed form.
    const double inertia = m * length_ * length_ / 12.0;
    const double cos2 = c * c;
    const double denominator = 1.0 + 3.0 * cos2;
    const double j = (1.0 + e) * m * u / denominator;
    const double spin = 6.0 * j * c / (m * length_);
    const double v_after = -u + j / m;
    const double end_after = v_after + spin * length_ / 2.0 * c;
    const double e_before = 0.5 * m * u * u;
    const double e_linear = 0.5 * m * v_after * v_after;
    const double e_rotational = 0.5 * inertia * spin * spin;
    const double e_after = e_linear + e_rotational;
    const double lost = 0.5 * (1.0 - e) * j * u;
    CHECK(std::abs(end_after - e * u) < 1e-12);
    CHECK(std::abs((e_before - e_after) - lost) < 1e-12);
    CHECK(std::abs(inertia - 1.0 / 6.0) < 1e-15);

    // The same with the engine and the reference: a thin rod (moment about its own axis 1e-4
    // of the others) and one contact point at its lower end.
    RigidBody rod;
    rod.inverse_mass = 1.0 / m;
    rod.inertia_body = Matrix3::diagonal({1e-4 * inertia, inertia, inertia});
    rod.orientation = from_axis_angle({0, 1, 0}, -theta);
    rod.position = {0, 0, 1};
    rod.velocity = {0, 0, -u};
    rod.restitution = e;
    rod.update_world_inertia();
    RigidBody ground = make_immovable_plane({0, 0, 1}, {0, 0, 0});
    const Vector3 end = rod.position - rotate(rod.orientation, Vector3{length_ / 2.0, 0, 0});
    const double engine_j = angular_impulse::impulse_magnitude(rod, ground, end, {0, 0, 1}, e);
    Contact contact;
    contact.normal = {0, 0, 1};
    contact.add_point(end, 0.001);
    angular_impulse::resolve(rod, ground, contact);
    CHECK(std::abs(engine_j - j) < 1e-12);
    CHECK(std::abs(rod.angular_velocity.y - spin) < 1e-9);
    CHECK(std::abs(rod.velocity.z - v_after) < 1e-12);
    CHECK(std::abs(angular_impulse::point_velocity(rod, end).z - end_after) < 1e-9);
    CHECK(std::abs(kinetic_energy(rod) - e_after) < 1e-9);

    const std::string times = " \\cdot ";
    const std::vector<std::string> printed{
        "m = " + page_quantity(m, "kg", digits),
        "L = " + page_quantity(length_, "m", digits),
        "\\theta = " + page_number(degrees, digits) + "^\\circ",
        "u = " + page_quantity(u, "m/s", digits),
        "e = " + page_number(e, digits),
        "I = m L^2/12 = \\tfrac{1}{6}\\,\\mathrm{kg\\,m^2}",
        "J = (1 + e)\\, m u / (1 + 3\\cos^2\\theta) = " + page_number(1.0 + e, digits) + times + page_number(m, digits) + times +
            page_number(u, digits) + " / " + page_number(denominator, digits) + " = " + page_quantity(j, "N\\,s", digits),
        "\\cos^2\\theta = " + page_number(cos2, digits),
        "\\omega' = 6 J \\cos\\theta / (m L) = " + page_quantity(spin, "rad/s", digits),
        "v' = -u + J/m = " + page_quantity(v_after, "m/s", digits),
        "u' = v' + \\omega' \\tfrac{L}{2}\\cos\\theta = " + page_quantity(end_after, "m/s", digits),
        "E = \\tfrac12 m u^2 = " + page_quantity(e_before, "J", digits),
        "E' = \\tfrac12 m v'^2 + \\tfrac12 I \\omega'^2 = " + page_number(e_linear, digits) + " + " +
            page_number(e_rotational, digits) + " = " + page_quantity(e_after, "J", digits),
        "\\Delta E = \\tfrac12 (1 - e) J u = " + page_quantity(lost, "J", digits),
    };
    // Once the formulas are gone, only the derivation's constants (3\cos^2, \tfrac{L}{2}, ^2),
    // step numbers and the 1e- of a tolerance may hold a digit.
    check_worked_example(chapter_page(), {.anchor = "{#angular_impulse_worked_example}",
                                          .formulas = printed,
                                          .symbolic_text = {"k = (1 + 3\\cos^2\\theta)/m", "angular_impulse_worked_example.cpp",
                                                            "\\tfrac{L}{2}", "3\\cos^2\\theta", "1 + 3\\cos", "^2", "(1 + e)", "step 3",
                                                            "step 5", "1e-"},
                                          .symbolic_patterns = {R"(\\tfrac12)"}});
}

TEST_CASE("chapter 4 exercise: the page names every public step test under its step", "[angular-impulse]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/angular_impulse.cpp");
    CHECK(found == 14);
}
