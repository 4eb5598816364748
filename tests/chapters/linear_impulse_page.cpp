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
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "linear-impulse.hpp"
#include "linear_impulse_scenes.hpp"
#include "workbook/probes.hpp"

using namespace workbook;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    INFO("reading " << path);
    REQUIRE(in.good());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string chapter_text() { return read_text(WORKBOOK_SOURCE_DIR "/chapters/linear-impulse/chapter.md"); }

std::string section(const std::string& text, const std::string& anchor) {
    const std::size_t heading = text.find(anchor);
    INFO("looking for the section " << anchor);
    REQUIRE(heading != std::string::npos);
    const std::size_t begin = text.rfind("\n## ", heading);
    const std::size_t end = text.find("\n## ", heading);
    return text.substr(begin == std::string::npos ? 0 : begin, end == std::string::npos ? std::string::npos : end - begin);
}

/// A number as the page prints it: `digits` significant digits, no trailing zeros.
std::string num(double value, int digits = 12) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    return out.str();
}

std::string quantity(double value, const std::string& unit) { return num(value) + "\\,\\mathrm{" + unit + "}"; }

bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

std::string remove_all(std::string text, const std::string& piece) {
    for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at)) text.erase(at, piece.size());
    return text;
}

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
        "m_1 = " + quantity(m1, "kg"),
        "v_1 = " + quantity(v1, "m/s"),
        "m_2 = " + quantity(m2, "kg"),
        "v_2 = " + quantity(v2, "m/s"),
        "e = " + num(e),
        "\\mathbf{n} = (-1, 0, 0)",
        "\\mathbf{v}_{12}\\cdot\\mathbf{n} = -(" + num(v1) + " - " + num(v2) + ") = " + quantity(vn, "m/s"),
        "w_1 + w_2 = " + num(w1) + " + " + num(w2) + " = " + quantity(w1 + w2, "kg^{-1}"),
        "\\lvert\\mathbf{n}\\rvert^2 = 1",
        "J = -(1 + " + num(e) + ")(" + num(vn) + ")/(1" + t + num(w1 + w2) + ") = " + quantity(j, "N\\,s"),
        "v_1' = " + num(v1) + " - " + num(w1) + t + num(j) + " = " + quantity(v1_after, "m/s"),
        "v_2' = " + num(v2) + " + " + num(w2) + t + num(j) + " = " + quantity(v2_after, "m/s"),
        "\\mathbf{v}_{12}'\\cdot\\mathbf{n} = -(" + num(v1_after) + " - " + num(v2_after) + ") = " + quantity(vn_after, "m/s"),
        "-e\\,\\mathbf{v}_{12}\\cdot\\mathbf{n} = -" + num(e) + t + "(" + num(vn) + ") = " + quantity(-e * vn, "m/s"),
        num(m1) + t + num(v1) + " + " + num(m2) + t + num(v2) + " = " + quantity(p_before, "kg\\,m/s"),
        num(m1) + t + num(v1_after) + " + " + num(m2) + t + num(v2_after) + " = " + quantity(p_after, "kg\\,m/s"),
        "E = " + half + t + num(m1) + t + num(v1) + "^2 + " + half + t + num(m2) + t + num(v2) + "^2 = " + quantity(e_before, "J"),
        "E' = " + half + t + num(m1) + t + num(v1_after) + "^2 + " + half + t + num(m2) + t + num(v2_after) + "^2 = " +
            quantity(e_after, "J"),
        "\\mu = \\tfrac{2}{3}\\,\\mathrm{kg}",
        "\\Delta E = " + half + t + "\\tfrac{2}{3}" + t + "(1 - " + num(e) + "^2)" + t + num(-vn) + "^2 = " + quantity(lost, "J"),
        quantity(lost_e0, "J") + "\\f$ at \\f$e = 0",
        quantity(lost_e1, "J") + "\\f$ at \\f$e = 1",
    };
    const std::string text = chapter_text();
    std::string example = section(text, "{#linear_impulse_worked_example}");
    for (const std::string& formula : printed) {
        INFO("the worked example should print: " << formula);
        CHECK(contains(example, formula));
    }
    for (const std::string& formula : printed) example = remove_all(example, formula);
    example = remove_all(example, "{#linear_impulse_worked_example}");
    example = remove_all(example, "linear_impulse_page.cpp");
    example = std::regex_replace(example, std::regex(R"([mvw]_[12]'?)"), "");
    example = std::regex_replace(example, std::regex(R"(_\{12\})"), "");
    example = std::regex_replace(example, std::regex(R"(\\tfrac12)"), "");
    example = std::regex_replace(example, std::regex(R"((steps?|[Cc]art|[Cc]hapter) [0-9](, [0-9])*( and [0-9])?)"), "");
    std::smatch leftover;
    if (std::regex_search(example, leftover, std::regex(R"([^\n]*[0-9][^\n]*)"))) {
        FAIL("the worked example prints a number no check covers, in: " << leftover.str());
    }
}

TEST_CASE("chapter 3 page: the numbers it quotes about its scenes", "[linear-impulse]") {
    const std::string text = chapter_text();
    const chapter3::BounceReport bounce = chapter3::bouncing_ball_report();
    REQUIRE(!bounce.apexes.empty());
    CHECK(contains(text, "the first against \\f$0.64\\,\\mathrm{m}\\f$"));
    CHECK(std::abs(std::pow(0.8, 2.0) - 0.64) < 1e-12);
    const chapter3::StackReport stack = chapter3::stacked_balls_report();
    CHECK(contains(text, "\\f$(29/11)^2 = " + num(stack.ideal_factor, 3) + "\\f$"));
    CHECK(contains(text, "rises " + num(stack.factor, 4) + "\n"));
    const double first = 100.0 * (bounce.apexes.front() - 0.64) / 0.64;
    const double sixth = 100.0 * (bounce.apexes.at(5) - std::pow(0.8, 12.0)) / std::pow(0.8, 12.0);
    CHECK(contains(text, "from \xE2\x88\x92" + num(-first, 2) + " % at the first apex"));
    CHECK(contains(text, "\xE2\x88\x92" + num(-sixth, 2) + " % at the sixth"));
    // "a tennis ball of one tenth its mass": the scene's masses.
    const chapter3::Run cradle = chapter3::run_scene("chapters/linear-impulse/scenes/newtons-cradle.json");
    CHECK(cradle.bodies.size() == 5);
    CHECK(contains(text, "three fifths of its speed"));
    CHECK(contains(text, "two fifths"));
}

TEST_CASE("chapter 3 exercise: the page names every public step test under its step", "[linear-impulse]") {
    const std::string text = chapter_text();
    const std::string tests = read_text(WORKBOOK_SOURCE_DIR "/tests/steps/linear_impulse.cpp");
    const std::regex test_case(R"re(TEST_CASE\("([^"]+)",\s*"\[linear-impulse\]\[step:([0-9]+):([a-z-]+)\])re");
    int found = 0;
    for (auto it = std::sregex_iterator(tests.begin(), tests.end(), test_case); it != std::sregex_iterator(); ++it) {
        ++found;
        const std::string name = (*it)[1].str();
        std::string title = (*it)[3].str();
        for (char& c : title)
            if (c == '-') c = ' ';
        const std::string heading = "### Step " + (*it)[2].str() + " \xC2\xB7 " + title;
        INFO("step heading: " << heading << "; test: " << name);
        const std::size_t begin = text.find(heading);
        REQUIRE(begin != std::string::npos);
        const std::size_t end = text.find("\n##", begin + heading.size());
        const std::string step_text = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        // A name may wrap across a line in the page.
        std::string flat = step_text;
        for (char& c : flat)
            if (c == '\n') c = ' ';
        flat = std::regex_replace(flat, std::regex(" +"), " ");
        CHECK(contains(flat, "`" + name + "`"));
    }
    CHECK(found == 11);
}
