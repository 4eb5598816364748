// Ties the text of chapter 2 (chapters/projection/chapter.md) to the code.
//
// 1. The worked example: every number it prints is recomputed here, in closed form and with
//    the engine (make_sphere, a World with the reference projection), formatted the way the
//    page prints it, and looked up in the page. Once every checked formula is removed from
//    the section, no digit may be left except symbolic indices such as m_1, so a number
//    added to the example without a check fails here.
// 2. The exercise: every public step test of tests/steps/projection.cpp is named in the page,
//    under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "projection.hpp"
#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

using namespace workbook;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    INFO("reading " << path);
    REQUIRE(in.good());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string chapter_text() { return read_text(WORKBOOK_SOURCE_DIR "/chapters/projection/chapter.md"); }

/// The lines from the heading that carries `anchor` up to the next heading of level 2.
std::string section(const std::string& text, const std::string& anchor) {
    const std::size_t heading = text.find(anchor);
    INFO("looking for the section " << anchor);
    REQUIRE(heading != std::string::npos);
    const std::size_t begin = text.rfind("\n## ", heading);
    const std::size_t end = text.find("\n## ", heading);
    return text.substr(begin == std::string::npos ? 0 : begin, end == std::string::npos ? std::string::npos : end - begin);
}

/// A number as the page prints it: at most 12 significant digits, no trailing zeros.
std::string num(double value) {
    std::ostringstream out;
    out.precision(12);
    out << value;
    return out.str();
}

/// A vector as the page prints it; + 0.0 turns a negative zero into the 0 a reader writes.
std::string vec(const Vector3& v) { return "(" + num(v.x + 0.0) + ", " + num(v.y + 0.0) + ", " + num(v.z + 0.0) + ")"; }

std::string quantity(double value, const std::string& unit) { return num(value) + "\\,\\mathrm{" + unit + "}"; }

/// A fraction as the page prints it, after checking that it is the computed value.
std::string fraction(double value, int numerator, int denominator) {
    CHECK(std::abs(value - static_cast<double>(numerator) / static_cast<double>(denominator)) < 1e-15);
    return "\\tfrac{" + std::to_string(numerator) + "}{" + std::to_string(denominator) + "}";
}

bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

std::string remove_all(std::string text, const std::string& piece) {
    for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at)) text.erase(at, piece.size());
    return text;
}

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
        "m_1 = " + quantity(m1, "kg"),
        "m_2 = " + quantity(m2, "kg"),
        "d = " + quantity(d, "m"),
        "\\mathbf{n} = " + vec(n),
        "w_1 = " + fraction(w1, 1, 3) + "\\,\\mathrm{kg^{-1}}",
        "w_2 = " + quantity(w2, "kg^{-1}"),
        "w_1/(w_1 + w_2) = " + fraction(share1, 1, 4),
        "w_2/(w_1 + w_2) = " + fraction(share2, 3, 4),
        "\\Delta\\mathbf{x}_1 = " + fraction(share1, 1, 4) + times + num(d) + "\\,\\mathbf{n} = " + vec(dx1) + "\\,\\mathrm{m}",
        "\\Delta\\mathbf{x}_2 = -" + fraction(share2, 3, 4) + times + num(d) + "\\,\\mathbf{n} = " + vec(dx2) + "\\,\\mathrm{m}",
        "m_1\\Delta\\mathbf{x}_1 + m_2\\Delta\\mathbf{x}_2 = " + num(m1) + times + vec(dx1) + " + " + num(m2) + times + vec(dx2) +
            " = \\mathbf{0}",
        "\\beta = " + num(beta),
        "s = " + quantity(slop, "m"),
        "d' = " + num(beta) + times + "(" + num(d) + " - " + num(slop) + ") = " + quantity(removed, "m"),
        "d_3 = " + num(slop) + " + (" + num(d) + " - " + num(slop) + ")" + times + num(1.0 - beta) + "^3 = " +
            quantity(after_three, "m"),
    };

    const std::string text = chapter_text();
    std::string example = section(text, "{#projection_worked_example}");
    for (const std::string& formula : printed) {
        INFO("the worked example should print: " << formula);
        CHECK(contains(example, formula));
    }
    {
        INFO("the worked example should say the light ball moves three times as far");
        CHECK(contains(example, "three times as far"));
    }

    for (const std::string& formula : printed) example = remove_all(example, formula);
    example = remove_all(example, "{#projection_worked_example}");
    example = remove_all(example, "projection_worked_example.cpp");
    example = std::regex_replace(example, std::regex(R"([mwd]_[123]\b)"), "");
    example = std::regex_replace(example, std::regex(R"((step|body) [0-9])"), "");
    std::smatch leftover;
    if (std::regex_search(example, leftover, std::regex(R"([^\n]*[0-9][^\n]*)"))) {
        FAIL("the worked example prints a number no check covers, in: " << leftover.str());
    }

    const std::size_t example_begin = text.find("{#projection_worked_example}");
    const std::size_t example_end = text.find("\n## ", example_begin);
    const std::string outside = text.substr(0, example_begin) + text.substr(example_end);
    if (std::regex_search(outside, leftover, std::regex(R"([0-9]\s*\\,\\mathrm\{[^}]*\})"))) {
        FAIL("a quantity with a unit appears outside the checked worked example: " << leftover.str());
    }
}

TEST_CASE("chapter 2 exercise: the page names every public step test under its step", "[projection]") {
    const std::string text = chapter_text();
    const std::string tests = read_text(WORKBOOK_SOURCE_DIR "/tests/steps/projection.cpp");
    const std::regex test_case(R"re(TEST_CASE\("([^"]+)",\s*"\[projection\]\[step:([0-9]+):([a-z-]+)\])re");
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
        // A long name may be wrapped across lines in the page; compare with whitespace collapsed.
        const std::string flat = std::regex_replace(step_text, std::regex(R"(\s+)"), " ");
        CHECK(contains(flat, "`" + name + "`"));
    }
    CHECK(found == 10);
}
