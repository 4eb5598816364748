// The clay-drop figure's caption (chapters/inelastic/chapter.md) and the scene's description
// state what the simulation shows, with the numbers it measures: the total drifting before
// impact, the energy lost, and the ball sinking into the ground afterwards.
#include <catch2/catch_test_macros.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "chapter_page.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

using workbook::testing::contains;
using workbook::testing::figure_caption;
using workbook::testing::read_chapter_page;

TEST_CASE("the clay-drop caption and description state what the figure shows", "[inelastic]") {
    std::vector<std::string_view> responders;
    for (const auto& model : workbook::response_models()) responders.push_back(model.name);
    const workbook::Scene scene =
        workbook::load_scene(WORKBOOK_SOURCE_DIR "/chapters/inelastic/scenes/clay-drop.json", responders);
    REQUIRE(scene.bodies.size() == 2);
    const workbook::RigidBody& ball = scene.bodies[0];
    REQUIRE_FALSE(ball.is_immovable());
    REQUIRE(scene.bodies[1].is_immovable());

    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const auto samples = workbook::run(world, scene.duration);
    const auto hit = std::find_if(samples.begin(), samples.end(), [](const auto& s) { return s.response_energy_change != 0.0; });
    REQUIRE(hit != samples.begin());
    REQUIRE(hit != samples.end());

    // The ball is the only body with potential energy: its height is E_p / (m g).
    const double weight = ball.mass() * length(scene.settings.gravity);
    const auto height = [&](const auto& sample) { return sample.potential / weight; };
    const double radius = ball.shape.radius;

    const double start = samples.front().total_energy();
    const double drift = std::prev(hit)->total_energy() - start;
    const double lost = -hit->response_energy_change;
    const double depth_at_contact = radius - height(*hit);
    const double depth_at_end = radius - height(samples.back());
    const double later_fall = hit->total_energy() - samples.back().total_energy();
    INFO("drift " << drift << " J, lost " << lost << " J, depth " << depth_at_contact << " m then " << depth_at_end
                  << " m, later fall " << later_fall << " J");
    REQUIRE(drift < 0.0);                        // it drifts down, as the text says
    REQUIRE(depth_at_end > depth_at_contact);    // it sinks, as the text says
    REQUIRE(depth_at_contact > 0.0);

    const std::string drift_text = fmt::format("drifts down by {:.3f} J ({:.1f} %)", -drift, -100.0 * drift / start);
    const std::string lost_text = fmt::format("{:.2f} J", lost);
    const std::string contact_text = fmt::format("{:.1f} cm into the ground when the contact is found", 100.0 * depth_at_contact);
    const std::string end_text = fmt::format("sinks to {:.1f} cm", 100.0 * depth_at_end);
    const std::string later_text = fmt::format("a further {:.3f} J", later_fall);

    const std::string caption = figure_caption(read_chapter_page(WORKBOOK_SOURCE_DIR, "inelastic"), "inelastic/clay-drop");
    for (const std::string& piece : {drift_text, lost_text, contact_text, end_text}) {
        INFO("caption: " << caption);
        CHECK(contains(caption, piece));
    }
    CHECK_FALSE(contains(caption, "rests on"));
    for (const std::string& piece : {drift_text, lost_text, contact_text, end_text, later_text}) {
        INFO("description: " << scene.description);
        CHECK(contains(scene.description, piece));
    }
}
