// Ties the text of chapter 2 (chapters/projection/chapter.md) to the code.
//
// 1. The worked example: every number it prints is recomputed here, in closed form and with
//    the engine (make_sphere, a World with the reference projection), formatted the way the
//    page prints it, and looked up in the page (tests/support/chapter_page.hpp). Once every
//    checked formula is removed from the section, no digit may be left except symbolic
//    indices such as m_1, so a number added to the example without a check fails here.
// 2. The exercise: every public step test of tests/steps/projection.cpp is named in the page,
//    under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "chapter_page.hpp"
#include "projection.hpp"
#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

using namespace workbook;
using namespace workbook::testing;

namespace {

ChapterPage chapter_page() { return read_chapter_page(WORKBOOK_SOURCE_DIR, "projection"); }

/// A vector as the page prints it; + 0.0 turns a negative zero into the 0 a reader writes.
std::string page_vector(const Vector3& v) {
    return "(" + page_number(v.x + 0.0) + ", " + page_number(v.y + 0.0) + ", " + page_number(v.z + 0.0) + ")";
}

/// The page's fractions (w_1 = 1/3 and the shares 1/4, 3/4) are below 1 and come out to rounding,
/// so a few units in the last place (1e-15) is the tolerance.
std::string fraction(double value, int numerator, int denominator) { return page_fraction(value, numerator, denominator, 1e-15); }

bool near(const Vector3& a, const Vector3& b) { return length(a - b) < 1e-15; }

}  // namespace

TEST_CASE("chapter 2 worked example: every number in the text is the physics", "[projection]") {
    // A 3 kg ball overlaps a 1 kg ball by 4 cm along (0.6, 0.8, 0).
    const double m1 = 3.0;
    const double m2 = 1.0;
    const double d = 0.04;
    const Vector3 n{0.6, 0.8, 0.0};
    CHECK(std::abs(length(n) - 1.0) < 1e-15);

    // Closed form.
    const double w1 = 1.0 / m1;
    const double w2 = 1.0 / m2;
    const double share1 = w1 / (w1 + w2);
    const double share2 = w2 / (w1 + w2);
    const Vector3 dx1 = n * (share1 * d);
    const Vector3 dx2 = -(n * (share2 * d));
    const Vector3 centre_shift = m1 * dx1 + m2 * dx2;
    const double beta = 0.2;
    const double slop = 0.01;
    const double removed = beta * (d - slop);
    const double after_three = slop + (d - slop) * std::pow(1.0 - beta, 3);
    CHECK(length(centre_shift) < 1e-17);
    CHECK(std::abs(length(dx2) / length(dx1) - 3.0) < 1e-12);  // "three times as far"

    // The same with the engine: the reference projection on two balls of radius 0.5 m.
    RigidBody heavy = make_sphere(m1, 0.5, n * (1.0 - d));
    RigidBody light = make_sphere(m2, 0.5, {0, 0, 0});
    const RigidBody heavy_before = heavy;
    const RigidBody light_before = light;
    Contact contact;
    contact.normal = n;
    contact.add_point(n * 0.5, d);
    projection::correct(heavy, light, contact, PositionCorrection{1.0, 0.0});
    CHECK(near(heavy.position - heavy_before.position, dx1));
    CHECK(near(light.position - light_before.position, dx2));
    CHECK(std::abs(projection::depth_to_remove(d, PositionCorrection{beta, slop}) - removed) < 1e-15);
    // Three passes of a World that only detects and corrects.
    World world({heavy_before, light_before}, WorldSettings{0.01, {}, Integrator::semi_implicit_euler, {beta, slop}},
                *find_response_model("projection"));
    for (int pass = 0; pass < 3; ++pass) {
        world.detect();
        world.correct();
    }
    CHECK(std::abs((1.0 - length(world.bodies()[0].position - world.bodies()[1].position)) - after_three) < 1e-14);

    const std::string times = " \\cdot ";
    const std::vector<std::string> printed{
        "m_1 = " + page_quantity(m1, "kg"),
        "m_2 = " + page_quantity(m2, "kg"),
        "d = " + page_quantity(d, "m"),
        "\\mathbf{n} = " + page_vector(n),
        "w_1 = " + fraction(w1, 1, 3) + "\\,\\mathrm{kg^{-1}}",
        "w_2 = " + page_quantity(w2, "kg^{-1}"),
        "w_1/(w_1 + w_2) = " + fraction(share1, 1, 4),
        "w_2/(w_1 + w_2) = " + fraction(share2, 3, 4),
        "\\Delta\\mathbf{x}_1 = " + fraction(share1, 1, 4) + times + page_number(d) + "\\,\\mathbf{n} = " + page_vector(dx1) +
            "\\,\\mathrm{m}",
        "\\Delta\\mathbf{x}_2 = -" + fraction(share2, 3, 4) + times + page_number(d) + "\\,\\mathbf{n} = " + page_vector(dx2) +
            "\\,\\mathrm{m}",
        "m_1\\Delta\\mathbf{x}_1 + m_2\\Delta\\mathbf{x}_2 = " + page_number(m1) + times + page_vector(dx1) + " + " +
            page_number(m2) + times + page_vector(dx2) + " = \\mathbf{0}",
        "\\beta = " + page_number(beta),
        "s = " + page_quantity(slop, "m"),
        "d' = " + page_number(beta) + times + "(" + page_number(d) + " - " + page_number(slop) + ") = " +
            page_quantity(removed, "m"),
        "d_3 = " + page_number(slop) + " + (" + page_number(d) + " - " + page_number(slop) + ")" + times +
            page_number(1.0 - beta) + "^3 = " + page_quantity(after_three, "m"),
    };

    // Once the formulas are gone, only indices (m_1, w_2, d_3, "step 2") may hold a digit.
    const ChapterPage page = chapter_page();
    const std::string anchor = "{#projection_worked_example}";
    check_worked_example(page, {.anchor = anchor,
                                .formulas = printed,
                                .symbolic_text = {"projection_worked_example.cpp"},
                                .symbolic_patterns = {R"([mwd]_[123]\b)", R"((step|body) [0-9])"}});
    {
        INFO("the worked example should say the light ball moves three times as far");
        CHECK(contains(section_with_anchor(page, anchor), "three times as far"));
    }
    check_units_only_in_worked_example(page, anchor);
}

TEST_CASE("chapter 2 exercise: the page names every public step test under its step", "[projection]") {
    const int found = check_step_tests_named_under_their_steps(chapter_page(), WORKBOOK_SOURCE_DIR "/tests/steps/projection.cpp");
    CHECK(found == 10);
}
