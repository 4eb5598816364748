// Ties each chapter page's "How accurate is this" section (chapters/<id>/chapter.md, the last
// section, full edition only) to the accuracy bench's families: every number it prints is
// measured here with the chapter's model and formatted as the page prints it, or is one of the
// family's parameters, checked against the family; once those are removed, no digit may be
// left. The section shows its family's figure.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "bench.hpp"
#include "families.hpp"
#include "models.hpp"

using namespace workbook;
using namespace workbook::accuracy;

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    INFO("reading " << path);
    REQUIRE(in.good());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The section from its heading to the \endif that closes it.
std::string accuracy_section(const std::string& chapter) {
    const std::string text = read_text(WORKBOOK_SOURCE_DIR "/chapters/" + chapter + "/chapter.md");
    const std::size_t start = text.find("## How accurate is this");
    INFO(chapter << ": the section \"How accurate is this\"");
    REQUIRE(start != std::string::npos);
    const std::size_t end = text.find("\\endif", start);
    REQUIRE(end != std::string::npos);
    // The last section of the page, inside \if full_edition (its figures need the solutions).
    CHECK(text.find("## ", start + 1) == std::string::npos);
    CHECK(text.rfind("\\if full_edition", start) != std::string::npos);
    return text.substr(start, end - start);
}

/// A relative error as the pages print it, in per cent with two significant digits.
std::string percent(double error) {
    std::ostringstream out;
    out.precision(2);
    out << error * 100.0;
    return out.str() + " %";
}

/// A value as the pages print it, with four significant digits.
std::string digits4(double value) {
    std::ostringstream out;
    out.precision(4);
    out << value;
    return out.str();
}

WorldSettings settings_for(double dt, Integrator integrator, ContactTiming timing) {
    WorldSettings s;
    s.time_step = dt;
    s.integrator = integrator;
    s.contact_timing = timing;
    return s;
}

WorldSettings discrete(double dt, Integrator integrator = Integrator::semi_implicit_euler) {
    return settings_for(dt, integrator, ContactTiming::discrete);
}

WorldSettings event(double dt) { return settings_for(dt, Integrator::exact_under_gravity, ContactTiming::event); }

/// `measured` must each be in the section; after removing them and `parameters` (longest
/// first), the paths and the anchor, no digit may be left.
void check_section(const std::string& chapter, const std::string& figure, const std::vector<std::string>& measured,
                   std::vector<std::string> parameters) {
    std::string section = accuracy_section(chapter);
    const std::string image = "\\image html accuracy/pareto-" + figure + ".svg";
    CHECK(section.find(image) != std::string::npos);
    for (const std::string& value : measured) {
        INFO(chapter << ": the measured value \"" << value << "\" is on the page");
        CHECK(section.find(value) != std::string::npos);
    }
    parameters.insert(parameters.end(), measured.begin(), measured.end());
    parameters.insert(parameters.end(), {image, "tests/accuracy/chapter_pages.cpp", "1/30", "1/3840", "1, 2 or 4"});
    std::sort(parameters.begin(), parameters.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    for (const std::string& piece : parameters)
        for (std::size_t at = section.find(piece); at != std::string::npos; at = section.find(piece, at))
            section.erase(at, piece.size());
    std::string left;
    for (std::size_t i = 0; i < section.size(); ++i)
        if (std::isdigit(static_cast<unsigned char>(section[i])) != 0)
            left += "..." + section.substr(i >= 20 ? i - 20 : 0, 40) + "...\n";
    INFO(chapter << ": digits not checked by this test:\n" << left);
    CHECK(left.empty());
}

}  // namespace

TEST_CASE("chapter 1's accuracy section: the inelastic head-on pair", "[accuracy][pages]") {
    HeadOn pair;
    pair.restitution = 0.0;
    const ResponseModel& inelastic = chapter_model("inelastic");
    // The parameters the page names.
    CHECK(pair.m1 == 1.0);
    CHECK(pair.v1 == 2.0);
    CHECK(pair.m2 == 3.0);
    CHECK(pair.v2 == -1.0);
    for (int fps : frame_rates()) CHECK(head_on_error(event(1.0 / fps), inelastic, pair).error <= 1e-12);
    check_section("inelastic", "head-on-inelastic",
                  {percent(head_on_error(discrete(1.0 / 60), inelastic, pair).error),
                   percent(head_on_error(discrete(1.0 / 240), inelastic, pair).error), "10^{-12}"},
                  {"1 kg", "2 m/s", "3 kg", "−1 m/s", "1 s", "1/60", "1/240"});
}

TEST_CASE("chapter 2's accuracy section: the resting stack", "[accuracy][pages]") {
    const ResponseModel model = inelastic_with_projection();
    const auto sink = [&model](double dt) { return resting_stack_error(discrete(dt), model, 3).error; };
    check_section("projection", "resting-stack", {percent(sink(1.0 / 60)), percent(sink(1.0 / 240)), percent(sink(1.0 / 960))},
                  {"1/60", "1/240", "1/960", "1 s", "fraction 1", "chapter 1"});
}

TEST_CASE("chapter 3's accuracy section: the bouncing ball and the cradle", "[accuracy][pages]") {
    const ResponseModel& linear = chapter_model("linear-impulse");
    const BouncingBall ball;
    CHECK(ball.h0 == 1.0);
    CHECK(ball.restitution == 0.8);
    // The 20 bounces within 1e-9 are checked in event_timing.cpp; the cradle at every step here.
    for (int fps : frame_rates()) CHECK(cradle_error(event(1.0 / fps), linear).error <= 1e-12);
    check_section("linear-impulse", "bouncing-ball",
                  {percent(bouncing_ball_error(discrete(1.0 / 60), linear).error),
                   percent(bouncing_ball_error(discrete(1.0 / 960), linear).error),
                   percent(cradle_error(discrete(1.0 / 60), linear).error), "10^{-9}", "10^{-12}"},
                  {"1 m", "e = 0.8", "e^{2k}h_0", "e^(2k) h0", "Box2D", "first ten", "first 20", "first 10", "1/60", "1/960"});
}

TEST_CASE("chapter 4's accuracy section: the tilted rod and the free box", "[accuracy][pages]") {
    const ResponseModel& angular = chapter_model("angular-impulse");
    const TiltedRod rod;
    TiltedRod thin;
    thin.thickness = 0.0;
    CHECK(rod.thickness == 0.05);
    CHECK(rod.impact_speed == 3.0);
    CHECK(rod.mass == 2.0);
    CHECK(rod.length == 1.0);
    CHECK(rod.tilt_degrees == 30.0);
    CHECK(rod.restitution == 0.5);
    for (int fps : frame_rates()) {
        INFO("dt = 1/" << fps);
        CHECK(tilted_rod_error(event(1.0 / fps), angular).error <= 1e-12);
        for (ContactTiming timing : {ContactTiming::discrete, ContactTiming::event})
            CHECK(torque_free_box_error(settings_for(1.0 / fps, Integrator::exact_under_gravity, timing), angular).error <=
                  1e-12);
    }
    const auto late = [&angular](double dt) {
        return tilted_rod_error(discrete(dt, Integrator::exact_under_gravity), angular).error;
    };
    check_section("angular-impulse", "tilted-rod",
                  {digits4(rod.impulse()) + " N s", digits4(thin.impulse()) + " N s", digits4(rod.spin_after()) + " rad/s",
                   percent(late(1.0 / 60)), percent(late(1.0 / 240)), "10^{-12}"},
                  {"5 cm", "3 m/s", "2 kg", "1 m by", "30 degrees", "e = 0.5", "10 s", "1/60", "1/240", "(1 + e)", "1/m",
                   "d^2"});
}
