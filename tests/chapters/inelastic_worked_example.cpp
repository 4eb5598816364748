// Ties the text of chapter 1 (chapters/inelastic/chapter.md) to the code.
//
// 1. The worked example: every number it prints is recomputed here, in closed form and with
//    the engine (make_sphere, kinetic_energy, and the reference common_velocity, resolve and
//    energy_lost), formatted the way the page prints it, and looked up in the page
//    (tests/support/chapter_page.hpp does the reading, formatting and looking up). After
//    every checked formula has been removed from the section, no digit may be left over
//    except symbolic indices such as m_1 or "body 2", so a number added to the example without a check
//    fails here.
// 2. The exercise: every public step test of tests/steps/inelastic.cpp is named in the
//    page, under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "chapter_page.hpp"
#include "inelastic.hpp"
#include "workbook/contact.hpp"
#include "workbook/probes.hpp"
#include "workbook/rigid_body.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "inelastic"); }

/// The page prints \tfrac{2}{3} for the reduced mass; the closed form gives it to rounding.
std::string fraction(double value, int numerator, int denominator) { return page_fraction(value, numerator, denominator, 1e-12); }

}  // namespace

TEST_CASE("chapter 1 worked example: every number in the text is the physics", "[inelastic]") {
    // The example: a 2 kg cart at 3 m/s runs into a 1 kg cart at rest, along x.
    const double m1 = 2.0;
    const double v1 = 3.0;
    const double m2 = 1.0;
    const double v2 = 0.0;

    // Closed form.
    const double p = m1 * v1 + m2 * v2;
    const double shared = p / (m1 + m2);
    const double w1 = 1.0 / m1;
    const double w2 = 1.0 / m2;
    const double shared_inverse = (w2 * v1 + w1 * v2) / (w1 + w2);
    const double p_after = (m1 + m2) * shared;
    const double e_before = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
    const double e_after = 0.5 * (m1 + m2) * shared * shared;
    const double mu = m1 * m2 / (m1 + m2);
    const double relative_speed = std::abs(v1 - v2);
    const double lost = 0.5 * mu * relative_speed * relative_speed;
    CHECK(std::abs(shared_inverse - shared) < 1e-12);
    CHECK(std::abs(p_after - p) < 1e-12);
    CHECK(std::abs((e_before - e_after) - lost) < 1e-12);

    // The same with the engine and the reference responder.
    RigidBody cart1 = make_sphere(m1, 0.1, {-0.15, 0, 0}, {v1, 0, 0});
    RigidBody cart2 = make_sphere(m2, 0.1, {0.0, 0, 0}, {v2, 0, 0});
    const double engine_e_before = kinetic_energy(cart1) + kinetic_energy(cart2);
    const Vector3 engine_shared = inelastic::common_velocity(cart1, cart2);
    const double engine_lost = inelastic::energy_lost(cart1, cart2);
    Contact contact;
    contact.normal = normalized(cart1.position - cart2.position);  // from body 2 towards body 1
    contact.add_point({-0.05, 0, 0}, 0.05);
    inelastic::resolve(cart1, cart2, contact);
    const double engine_e_after = kinetic_energy(cart1) + kinetic_energy(cart2);
    const Vector3 engine_p_after = cart1.mass() * cart1.velocity + cart2.mass() * cart2.velocity;
    CHECK(std::abs(engine_e_before - e_before) < 1e-12);
    CHECK(std::abs(engine_shared.x - shared) < 1e-12);
    CHECK(engine_shared.y == 0.0);
    CHECK(engine_shared.z == 0.0);
    CHECK(std::abs(cart1.velocity.x - shared) < 1e-12);
    CHECK(std::abs(cart2.velocity.x - shared) < 1e-12);
    CHECK(std::abs(engine_p_after.x - p) < 1e-12);
    CHECK(std::abs(engine_e_after - e_after) < 1e-12);
    CHECK(std::abs(engine_lost - lost) < 1e-12);

    // Each formula of the section, built from the computed numbers.
    const std::string times = " \\cdot ";
    const std::string half = "\\tfrac12";
    const std::vector<std::string> printed{
        "m_1 = " + page_quantity(m1, "kg"),
        "v_1 = " + page_quantity(v1, "m/s"),
        "m_2 = " + page_quantity(m2, "kg"),
        "v_2 = " + page_quantity(v2, "m/s"),
        "p = m_1 v_1 + m_2 v_2 = " + page_number(m1) + times + page_number(v1) + " + " + page_number(m2) + times +
            page_number(v2) + " = " + page_quantity(p, "kg\\,m/s"),
        "v' = p / (m_1 + m_2) = " + page_number(p) + " / " + page_number(m1 + m2) + " = " + page_quantity(shared, "m/s"),
        "w_1 = " + page_quantity(w1, "kg^{-1}"),
        "w_2 = " + page_quantity(w2, "kg^{-1}"),
        "(w_2 v_1 + w_1 v_2)/(w_1 + w_2) = (" + page_number(w2) + times + page_number(v1) + " + " + page_number(w1) + times +
            page_number(v2) + ")/" + page_number(w1 + w2) + " = " + page_quantity(shared_inverse, "m/s"),
        "(m_1 + m_2)\\,v' = " + page_quantity(p_after, "kg\\,m/s"),
        "E = " + half + times + page_number(m1) + times + page_number(v1) + "^2 + " + half + times + page_number(m2) + times +
            page_number(v2) + "^2 = " + page_quantity(e_before, "J"),
        "E' = " + half + times + page_number(m1 + m2) + times + page_number(shared) + "^2 = " + page_quantity(e_after, "J"),
        "\\mu = (" + page_number(m1) + times + page_number(m2) + ")/(" + page_number(m1) + " + " + page_number(m2) +
            ") = " + fraction(mu, 2, 3) + "\\,\\mathrm{kg}",
        "\\lvert v_1 - v_2\\rvert = " + page_quantity(relative_speed, "m/s"),
        "\\Delta E = " + half + times + fraction(mu, 2, 3) + times + page_number(relative_speed) + "^2 = " +
            page_quantity(lost, "J"),
    };
    // "A third of the kinetic energy is gone", and the general fraction m2 / (m1 + m2) it quotes.
    CHECK(std::abs(lost / e_before - 1.0 / 3.0) < 1e-12);
    CHECK(std::abs(lost / e_before - m2 / (m1 + m2)) < 1e-12);

    // Once the formulas are gone, only indices (m_1, "body 2") and \tfrac12 may hold a digit.
    const ChapterPage page = chapter_page();
    const std::string anchor = "{#inelastic_worked_example}";
    check_worked_example(page, {.anchor = anchor,
                                .formulas = printed,
                                .symbolic_text = {"inelastic_worked_example.cpp"},
                                .symbolic_patterns = {R"([mvw]_[12]\b)", R"(\\tfrac12)", R"((step|body) [0-9])"}});
    {
        INFO("the worked example should say what fraction is lost: A third");
        CHECK(contains(section_with_anchor(page, anchor), "A third of the kinetic energy"));
    }
    check_units_only_in_worked_example(page, anchor);
}

TEST_CASE("chapter 1 exercise: the page names every public step test under its step", "[inelastic]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/inelastic.cpp");
    CHECK(found > 0);
}
