// Ties the text of chapter 4 (chapters/angular-impulse/chapter.md) to the code.
//
// 1. The worked example (the tilted rod): every number it prints is recomputed here, in closed
//    form and with the reference responder, formatted as the page prints it and looked up in
//    the page; once the checked formulas are removed, no digit may be left in the section.
// 2. The exercise: every public step test of tests/steps/angular_impulse.cpp is named in the
//    page, under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "angular-impulse.hpp"
#include "workbook/contact.hpp"
#include "workbook/probes.hpp"
#include "workbook/rigid_body.hpp"

using namespace workbook;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    INFO("reading " << path);
    REQUIRE(in.good());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string chapter_text() { return read_text(WORKBOOK_SOURCE_DIR "/chapters/angular-impulse/chapter.md"); }

/// A number as the page prints it: four significant digits, no trailing zeros.
std::string num(double value) {
    std::ostringstream out;
    out.precision(4);
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
        "m = " + quantity(m, "kg"),
        "L = " + quantity(length_, "m"),
        "\\theta = " + num(degrees) + "^\\circ",
        "u = " + quantity(u, "m/s"),
        "e = " + num(e),
        "I = m L^2/12 = \\tfrac{1}{6}\\,\\mathrm{kg\\,m^2}",
        "J = (1 + e)\\, m u / (1 + 3\\cos^2\\theta) = " + num(1.0 + e) + times + num(m) + times + num(u) + " / " + num(denominator) +
            " = " + quantity(j, "N\\,s"),
        "\\cos^2\\theta = " + num(cos2),
        "\\omega' = 6 J \\cos\\theta / (m L) = " + quantity(spin, "rad/s"),
        "v' = -u + J/m = " + quantity(v_after, "m/s"),
        "u' = v' + \\omega' \\tfrac{L}{2}\\cos\\theta = " + quantity(end_after, "m/s"),
        "E = \\tfrac12 m u^2 = " + quantity(e_before, "J"),
        "E' = \\tfrac12 m v'^2 + \\tfrac12 I \\omega'^2 = " + num(e_linear) + " + " + num(e_rotational) + " = " + quantity(e_after, "J"),
        "\\Delta E = \\tfrac12 (1 - e) J u = " + quantity(lost, "J"),
    };
    const std::string text = chapter_text();
    const std::size_t begin = text.find("{#angular_impulse_worked_example}");
    REQUIRE(begin != std::string::npos);
    const std::size_t finish = text.find("\n## ", begin);
    std::string example = text.substr(begin, finish - begin);
    for (const std::string& formula : printed) {
        INFO("the worked example should print: " << formula);
        CHECK(contains(example, formula));
    }
    for (const std::string& formula : printed) example = remove_all(example, formula);
    // Symbolic formulas, whose only digits are constants of the derivation.
    for (const std::string symbolic : {"k = (1 + 3\\cos^2\\theta)/m", "{#angular_impulse_worked_example}", "angular_impulse_worked_example.cpp", "\\tfrac{L}{2}",
                                       "3\\cos^2\\theta", "1 + 3\\cos", "^2", "(1 + e)", "step 3", "step 5", "1e-"})
        example = remove_all(example, symbolic);
    example = std::regex_replace(example, std::regex(R"(\\tfrac12)"), "");
    std::smatch leftover;
    if (std::regex_search(example, leftover, std::regex(R"([^\n]*[0-9][^\n]*)")))
        FAIL("the worked example prints a number no check covers, in: " << leftover.str());
}

TEST_CASE("chapter 4 exercise: the page names every public step test under its step", "[angular-impulse]") {
    const std::string text = chapter_text();
    const std::string tests = read_text(WORKBOOK_SOURCE_DIR "/tests/steps/angular_impulse.cpp");
    const std::regex test_case(R"re(TEST_CASE\("([^"]+)",\s*"\[angular-impulse\]\[step:([0-9]+):([a-z-]+)\])re");
    int found = 0;
    for (auto it = std::sregex_iterator(tests.begin(), tests.end(), test_case); it != std::sregex_iterator(); ++it) {
        ++found;
        const std::string name = (*it)[1].str();
        std::string title = (*it)[3].str();
        for (char& ch : title)
            if (ch == '-') ch = ' ';
        const std::string heading = "### Step " + (*it)[2].str() + " \xC2\xB7 " + title;
        INFO("step heading: " << heading << "; test: " << name);
        const std::size_t begin = text.find(heading);
        REQUIRE(begin != std::string::npos);
        const std::size_t end = text.find("\n##", begin + heading.size());
        const std::string step_text = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        // The page may wrap a long name over two lines.
        std::string flat = std::regex_replace(step_text, std::regex(R"(\s*\n\s*)"), " ");
        CHECK(contains(flat, "`" + name + "`"));
    }
    CHECK(found == 13);
}
