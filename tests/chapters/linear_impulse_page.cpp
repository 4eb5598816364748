// Ties the text of chapter 3 (chapters/linear-impulse/chapter.md) to the code.
//
// 1. The worked example: every number it prints is recomputed here, in closed form and with
//    the reference responder, formatted the way the page prints it, and looked up in the
//    page. Once every checked formula is removed from the section, no digit may be left over
//    except symbolic indices (m_1, v_{12}, "step 3"), so an unchecked number fails here.
// 2. The numbers the page quotes about its scenes (apexes, the stacked balls' factors).
// 3. The exercise: every public step test is named under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "chapter_page.hpp"
#include "linear-impulse.hpp"
#include "linear_impulse_scenes.hpp"
#include "workbook/probes.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "linear-impulse"); }

}  // namespace

TEST_CASE("chapter 3 worked example: every number in the text is the physics", "[linear-impulse]") {
    const double m1 = 2.0, v1 = 3.0, m2 = 1.0, v2 = 0.0, e = 0.5;
    const double w1 = 1.0 / m1, w2 = 1.0 / m2;
    const double vn = -(v1 - v2);  // the normal points along -x
    const double j = -(1.0 + e) * vn / (1.0 * (w1 + w2));
    const double v1_after = v1 - w1 * j;
    const double v2_after = v2 + w2 * j;
    const double vn_after = -(v1_after - v2_after);
    const double p_before = m1 * v1 + m2 * v2;
    const double p_after = m1 * v1_after + m2 * v2_after;
    const double e_before = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
    const double e_after = 0.5 * m1 * v1_after * v1_after + 0.5 * m2 * v2_after * v2_after;
    const double mu = 1.0 / (w1 + w2);
    const double lost = 0.5 * mu * (1.0 - e * e) * vn * vn;
    CHECK(std::abs(vn_after + e * vn) < 1e-12);
    CHECK(std::abs(p_after - p_before) < 1e-12);
    CHECK(std::abs((e_before - e_after) - lost) < 1e-12);
    CHECK(std::abs(mu - 2.0 / 3.0) < 1e-12);
    const double lost_e0 = 0.5 * mu * vn * vn;
    const double lost_e1 = 0.0;

    // The same with the engine and the reference responder.
    RigidBody cart1 = make_sphere(m1, 0.1, {-0.15, 0, 0}, {v1, 0, 0});
    RigidBody cart2 = make_sphere(m2, 0.1, {0.0, 0, 0}, {v2, 0, 0});
    cart1.restitution = cart2.restitution = e;
    Contact contact;
    contact.normal = normalized(cart1.position - cart2.position);
    contact.add_point({-0.05, 0, 0}, 0.05);
    CHECK(contact.normal == Vector3{-1, 0, 0});
    CHECK(std::abs(linear_impulse::relative_normal_velocity(cart1, cart2, contact.normal) - vn) < 1e-12);
    CHECK(std::abs(linear_impulse::impulse_magnitude(cart1, cart2, contact.normal, e) - j) < 1e-12);
    linear_impulse::resolve(cart1, cart2, contact);
    CHECK(std::abs(cart1.velocity.x - v1_after) < 1e-12);
    CHECK(std::abs(cart2.velocity.x - v2_after) < 1e-12);
    CHECK(std::abs(kinetic_energy(cart1) + kinetic_energy(cart2) - e_after) < 1e-12);

    const std::string t = " \\cdot ";
    const std::string half = "\\tfrac12";
    const std::vector<std::string> printed{
        "m_1 = " + page_quantity(m1, "kg"),
        "v_1 = " + page_quantity(v1, "m/s"),
        "m_2 = " + page_quantity(m2, "kg"),
        "v_2 = " + page_quantity(v2, "m/s"),
        "e = " + page_number(e),
        "\\mathbf{n} = (-1, 0, 0)",
        "\\mathbf{v}_{12}\\cdot\\mathbf{n} = -(" + page_number(v1) + " - " + page_number(v2) + ") = " + page_quantity(vn, "m/s"),
        "w_1 + w_2 = " + page_number(w1) + " + " + page_number(w2) + " = " + page_quantity(w1 + w2, "kg^{-1}"),
        "\\lvert\\mathbf{n}\\rvert^2 = 1",
        "J = -(1 + " + page_number(e) + ")(" + page_number(vn) + ")/(1" + t + page_number(w1 + w2) + ") = " +
            page_quantity(j, "N\\,s"),
        "v_1' = " + page_number(v1) + " - " + page_number(w1) + t + page_number(j) + " = " + page_quantity(v1_after, "m/s"),
        "v_2' = " + page_number(v2) + " + " + page_number(w2) + t + page_number(j) + " = " + page_quantity(v2_after, "m/s"),
        "\\mathbf{v}_{12}'\\cdot\\mathbf{n} = -(" + page_number(v1_after) + " - " + page_number(v2_after) + ") = " +
            page_quantity(vn_after, "m/s"),
        "-e\\,\\mathbf{v}_{12}\\cdot\\mathbf{n} = -" + page_number(e) + t + "(" + page_number(vn) + ") = " +
            page_quantity(-e * vn, "m/s"),
        page_number(m1) + t + page_number(v1) + " + " + page_number(m2) + t + page_number(v2) + " = " +
            page_quantity(p_before, "kg\\,m/s"),
        page_number(m1) + t + page_number(v1_after) + " + " + page_number(m2) + t + page_number(v2_after) + " = " +
            page_quantity(p_after, "kg\\,m/s"),
        "E = " + half + t + page_number(m1) + t + page_number(v1) + "^2 + " + half + t + page_number(m2) + t + page_number(v2) +
            "^2 = " + page_quantity(e_before, "J"),
        "E' = " + half + t + page_number(m1) + t + page_number(v1_after) + "^2 + " + half + t + page_number(m2) + t +
            page_number(v2_after) + "^2 = " + page_quantity(e_after, "J"),
        "\\mu = \\tfrac{2}{3}\\,\\mathrm{kg}",
        "\\Delta E = " + half + t + "\\tfrac{2}{3}" + t + "(1 - " + page_number(e) + "^2)" + t + page_number(-vn) + "^2 = " +
            page_quantity(lost, "J"),
        page_quantity(lost_e0, "J") + "\\f$ at \\f$e = 0",
        page_quantity(lost_e1, "J") + "\\f$ at \\f$e = 1",
    };
    // Once the formulas are gone, only indices (m_1, v_2', v_{12}), \tfrac12 and the numbers of
    // steps, carts and chapters may hold a digit.
    check_worked_example(chapter_page(),
                         {.anchor = "{#linear_impulse_worked_example}",
                          .formulas = printed,
                          .symbolic_text = {"linear_impulse_page.cpp"},
                          .symbolic_patterns = {R"([mvw]_[12]'?)", R"(_\{12\})", R"(\\tfrac12)",
                                                R"((steps?|[Cc]art|[Cc]hapter) [0-9](, [0-9])*( and [0-9])?)"}});
}

TEST_CASE("chapter 3 page: the numbers it quotes about its scenes", "[linear-impulse]") {
    const std::string text = chapter_page().text;
    const chapter3::BounceReport bounce = chapter3::bouncing_ball_report();
    REQUIRE(!bounce.apexes.empty());
    CHECK(contains(text, "the first against \\f$0.64\\,\\mathrm{m}\\f$"));
    CHECK(std::abs(std::pow(0.8, 2.0) - 0.64) < 1e-12);
    const chapter3::StackReport stack = chapter3::stacked_balls_report();
    CHECK(contains(text, "\\f$(29/11)^2 = " + page_number(stack.ideal_factor, 3) + "\\f$"));
    CHECK(contains(text, "rises " + page_number(stack.factor, 4) + "\n"));
    const double first = 100.0 * (bounce.apexes.front() - 0.64) / 0.64;
    const double sixth = 100.0 * (bounce.apexes.at(5) - std::pow(0.8, 12.0)) / std::pow(0.8, 12.0);
    CHECK(contains(text, "from \xE2\x88\x92" + page_number(-first, 2) + " % at the first apex"));
    CHECK(contains(text, "\xE2\x88\x92" + page_number(-sixth, 2) + " % at the sixth"));
    // "a tennis ball of one tenth its mass": the scene's masses.
    const chapter3::Run cradle = chapter3::run_scene("chapters/linear-impulse/scenes/newtons-cradle.json");
    CHECK(cradle.bodies.size() == 5);
    CHECK(contains(text, "three fifths of its speed"));
    CHECK(contains(text, "two fifths"));
}

TEST_CASE("chapter 3 exercise: the page names every public step test under its step", "[linear-impulse]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/linear_impulse.cpp");
    CHECK(found == 11);
}
