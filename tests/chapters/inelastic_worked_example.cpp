// Ties the text of chapter 1 (chapters/inelastic/chapter.md) to the code.
//
// 1. The worked example: every number it prints is recomputed here, in closed form and with
//    the engine (make_sphere, kinetic_energy, and the reference common_velocity, resolve and
//    energy_lost), formatted the way the page prints it, and looked up in the page. After
//    every checked formula has been removed from the section, no digit may be left over
//    except symbolic indices such as m_1 or "body 2", so a number added to the example without a check
//    fails here.
// 2. The exercise: every public step test of tests/steps/inelastic.cpp is named in the
//    page, under the heading of its own step.
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "inelastic.hpp"
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

std::string chapter_text() { return read_text(WORKBOOK_SOURCE_DIR "/chapters/inelastic/chapter.md"); }

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

/// A quantity as the page prints it inside a formula: 6\,\mathrm{kg\,m/s}.
std::string quantity(double value, const std::string& unit) { return num(value) + "\\,\\mathrm{" + unit + "}"; }

/// A fraction as the page prints it, after checking that it is the computed value.
std::string fraction(double value, int numerator, int denominator) {
    CHECK(std::abs(value - static_cast<double>(numerator) / static_cast<double>(denominator)) < 1e-12);
    return "\\tfrac{" + std::to_string(numerator) + "}{" + std::to_string(denominator) + "}";
}

bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

std::string remove_all(std::string text, const std::string& piece) {
    for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at)) text.erase(at, piece.size());
    return text;
}

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
        "m_1 = " + quantity(m1, "kg"),
        "v_1 = " + quantity(v1, "m/s"),
        "m_2 = " + quantity(m2, "kg"),
        "v_2 = " + quantity(v2, "m/s"),
        "p = m_1 v_1 + m_2 v_2 = " + num(m1) + times + num(v1) + " + " + num(m2) + times + num(v2) + " = " +
            quantity(p, "kg\\,m/s"),
        "v' = p / (m_1 + m_2) = " + num(p) + " / " + num(m1 + m2) + " = " + quantity(shared, "m/s"),
        "w_1 = " + quantity(w1, "kg^{-1}"),
        "w_2 = " + quantity(w2, "kg^{-1}"),
        "(w_2 v_1 + w_1 v_2)/(w_1 + w_2) = (" + num(w2) + times + num(v1) + " + " + num(w1) + times + num(v2) + ")/" +
            num(w1 + w2) + " = " + quantity(shared_inverse, "m/s"),
        "(m_1 + m_2)\\,v' = " + quantity(p_after, "kg\\,m/s"),
        "E = " + half + times + num(m1) + times + num(v1) + "^2 + " + half + times + num(m2) + times + num(v2) +
            "^2 = " + quantity(e_before, "J"),
        "E' = " + half + times + num(m1 + m2) + times + num(shared) + "^2 = " + quantity(e_after, "J"),
        "\\mu = (" + num(m1) + times + num(m2) + ")/(" + num(m1) + " + " + num(m2) + ") = " + fraction(mu, 2, 3) +
            "\\,\\mathrm{kg}",
        "\\lvert v_1 - v_2\\rvert = " + quantity(relative_speed, "m/s"),
        "\\Delta E = " + half + times + fraction(mu, 2, 3) + times + num(relative_speed) + "^2 = " + quantity(lost, "J"),
    };
    // "A third of the kinetic energy is gone", and the general fraction m2 / (m1 + m2) it quotes.
    CHECK(std::abs(lost / e_before - 1.0 / 3.0) < 1e-12);
    CHECK(std::abs(lost / e_before - m2 / (m1 + m2)) < 1e-12);

    const std::string text = chapter_text();
    std::string example = section(text, "{#inelastic_worked_example}");
    for (const std::string& formula : printed) {
        INFO("the worked example should print: " << formula);
        CHECK(contains(example, formula));
    }
    {
        INFO("the worked example should say what fraction is lost: A third");
        CHECK(contains(example, "A third of the kinetic energy"));
    }

    // Nothing numeric may remain once the checked formulas and the symbolic indices are gone.
    for (const std::string& formula : printed) example = remove_all(example, formula);
    example = remove_all(example, "{#inelastic_worked_example}");
    example = remove_all(example, "inelastic_worked_example.cpp");
    example = std::regex_replace(example, std::regex(R"([mvw]_[12]\b)"), "");
    example = std::regex_replace(example, std::regex(R"(\\tfrac12)"), "");
    example = std::regex_replace(example, std::regex(R"((step|body) [0-9])"), "");
    std::smatch leftover;
    if (std::regex_search(example, leftover, std::regex(R"([^\n]*[0-9][^\n]*)"))) {
        FAIL("the worked example prints a number no check covers, in: " << leftover.str());
    }

    // Quantities with units belong in the checked example only.
    const std::size_t example_begin = text.find("{#inelastic_worked_example}");
    const std::size_t example_end = text.find("\n## ", example_begin);
    const std::string outside = text.substr(0, example_begin) + text.substr(example_end);
    if (std::regex_search(outside, leftover, std::regex(R"([0-9]\s*\\,\\mathrm\{[^}]*\})"))) {
        FAIL("a quantity with a unit appears outside the checked worked example: " << leftover.str());
    }
}

TEST_CASE("chapter 1 exercise: the page names every public step test under its step", "[inelastic]") {
    const std::string text = chapter_text();
    const std::string tests = read_text(WORKBOOK_SOURCE_DIR "/tests/steps/inelastic.cpp");
    const std::regex test_case(R"re(TEST_CASE\("([^"]+)",\s*"\[inelastic\]\[step:([0-9]+):([a-z-]+)\])re");
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
        CHECK(contains(step_text, "`" + name + "`"));
    }
    CHECK(found > 0);
}
