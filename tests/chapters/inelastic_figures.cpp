// Ties the chapter's figures to the physics: every scene of chapters/inelastic/scenes is run,
// written to CSV exactly as the figure generator receives it, read back, and checked against
// the closed form of a perfectly inelastic collision. A new scene file is checked without
// touching this file.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "csv_table.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

namespace fs = std::filesystem;
using workbook::RigidBody;
using workbook::testing::CsvTable;
using workbook::testing::read_csv;
using workbook::testing::split_csv_line;
using workbook::Vector3;

constexpr double epsilon = std::numeric_limits<double>::epsilon();

std::vector<fs::path> scene_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(WORKBOOK_SOURCE_DIR) / "chapters" / "inelastic" / "scenes"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// The velocity a body has when the responder sees it in step `step` (1-based): semi-implicit
/// Euler adds g dt once per step before detection, and an immovable body never moves.
Vector3 velocity_at_step(const RigidBody& body, const workbook::WorldSettings& settings, std::size_t step) {
    if (body.is_immovable()) return body.velocity;
    return body.velocity + settings.gravity * (static_cast<double>(step) * settings.time_step);
}

double kinetic_at_step(const workbook::Scene& scene, std::size_t step) {
    double sum = 0.0;
    for (const RigidBody& body : scene.bodies)
        if (!body.is_immovable()) sum += 0.5 * body.mass() * length_squared(velocity_at_step(body, scene.settings, step));
    return sum;
}

}  // namespace

TEST_CASE("Every inelastic scene's CSV keeps momentum and loses 1/2 mu |v1 - v2|^2 at impact", "[inelastic]") {
    const std::vector<fs::path> files = scene_files();
    REQUIRE(files.size() >= 4);

    std::vector<std::string_view> responders;
    for (const auto& model : workbook::response_models()) responders.push_back(model.name);

    for (const fs::path& file : files) {
        DYNAMIC_SECTION(file.filename().string()) {
            const workbook::Scene scene = workbook::load_scene(file, responders);
            CHECK(scene.responder == "inelastic");
            CHECK_FALSE(scene.description.empty());
            INFO("the closed form below is for one colliding pair, so a scene of this chapter has two bodies");
            REQUIRE(scene.bodies.size() == 2);

            workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
            std::ostringstream csv;
            workbook::write_csv(csv, workbook::run(world, scene.duration));
            const CsvTable table = read_csv(csv.str());
            REQUIRE(table.names == split_csv_line(workbook::csv_header()));
            REQUIRE(table.rows.size() == workbook::step_count(scene.duration, scene.settings.time_step) + 1);

            const std::vector<double> response = table.column("response_energy_change");
            const std::vector<double> contacts = table.column("contacts");
            const auto hit = std::find_if(response.begin(), response.end(), [](double v) { return v != 0.0; });
            INFO("the bodies must meet within the scene's duration");
            REQUIRE(hit != response.end());
            const auto k = static_cast<std::size_t>(hit - response.begin());
            INFO("impact at step " << k << ", t = " << table.rows[k][0] << " s");
            REQUIRE(k >= 1);
            REQUIRE(contacts[k] == 1.0);
            const double mid_run = 0.5 * scene.duration;
            CHECK(std::abs(table.rows[k][0] - mid_run) < 0.25 * scene.duration);  // the impact sits mid-figure

            // Closed form from the scene's initial velocities.
            const RigidBody& b1 = scene.bodies[0];
            const RigidBody& b2 = scene.bodies[1];
            const double reduced_mass = 1.0 / (b1.inverse_mass + b2.inverse_mass);
            const Vector3 relative = velocity_at_step(b1, scene.settings, k) - velocity_at_step(b2, scene.settings, k);
            const double expected_loss = 0.5 * reduced_mass * length_squared(relative);
            INFO("1/2 mu |v1 - v2|^2 = " << expected_loss << " J");
            REQUIRE(expected_loss > 0.0);

            // The kinetic-energy drop as the CSV shows it; under gravity the step's gravity kick
            // (closed form) is taken out, so that only the response remains.
            std::vector<double> kinetic = table.column("kinetic_linear");
            const std::vector<double> rotational = table.column("kinetic_rotational");
            for (std::size_t i = 0; i < kinetic.size(); ++i) kinetic[i] += rotational[i];
            const double gravity_work = kinetic_at_step(scene, k) - kinetic_at_step(scene, k - 1);
            const double drop = kinetic[k] - kinetic[k - 1] - gravity_work;
            // Relative to the kinetic energy the difference is taken from, at 1e-12.
            const double tolerance = 1e-12 * std::max(expected_loss, kinetic_at_step(scene, k));
            INFO("CSV kinetic-energy drop " << drop << " J, response_energy_change " << response[k] << " J");
            CHECK(std::abs(drop + expected_loss) <= tolerance);
            CHECK(std::abs(response[k] + expected_loss) <= tolerance);
            CHECK(std::abs(response[k] - drop) <= tolerance);

            const bool gravity = scene.settings.gravity != Vector3{};
            if (!gravity) {
                // Once merged, the pair moves as one: no later step loses anything.
                for (std::size_t i = k + 1; i < response.size(); ++i) CHECK(response[i] == 0.0);
            }

            // Momentum flat to rounding over the whole run, when nothing outside the pair acts.
            const bool closed_system = !gravity && !b1.is_immovable() && !b2.is_immovable();
            if (closed_system) {
                // The size of the sum's terms, so a pair with zero total momentum is covered too.
                const double scale = b1.mass() * length(b1.velocity) + b2.mass() * length(b2.velocity);
                const double momentum_tolerance = 4.0 * epsilon * scale;
                const std::vector<double> px = table.column("momentum_x");
                const std::vector<double> py = table.column("momentum_y");
                const std::vector<double> pz = table.column("momentum_z");
                double worst = 0.0;
                for (std::size_t i = 0; i < px.size(); ++i)
                    worst = std::max({worst, std::abs(px[i] - px[0]), std::abs(py[i] - py[0]), std::abs(pz[i] - pz[0])});
                INFO("largest momentum change " << worst << " kg m/s, allowed " << momentum_tolerance << " kg m/s");
                CHECK(worst <= momentum_tolerance);
            }
        }
    }
}
