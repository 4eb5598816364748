// workbook-sim: runs a scene file with the linked responders and writes its probes.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "summary.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

std::vector<std::string_view> responder_names() {
    std::vector<std::string_view> names;
    for (const auto& model : workbook::response_models()) names.push_back(model.name);
    return names;
}

int run_scene(const std::string& scene_path, const std::string& csv_path, bool quiet) {
    const auto names = responder_names();
    const workbook::Scene scene = workbook::load_scene(scene_path, names);
    workbook::World world = workbook::make_world(scene, *workbook::find_response_model(scene.responder));
    const auto samples = workbook::run(world, scene.duration);

    if (!csv_path.empty()) {
        std::ofstream out(csv_path);
        if (!out) {
            fmt::print(stderr, "error: cannot write {}\n", csv_path);
            return 1;
        }
        workbook::write_csv(out, samples);
        if (!out.flush()) {
            fmt::print(stderr, "error: writing {} failed\n", csv_path);
            return 1;
        }
    } else if (quiet) {
        workbook::write_csv(std::cout, samples);
    }
    if (!quiet) workbook::sim::print_summary(std::cout, scene, samples);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Runs collision-response scenes of the Collision Response Workbook."};
    app.require_subcommand(1);

    std::string scene_path;
    std::string csv_path;
    bool quiet = false;
    auto* run = app.add_subcommand("run", "Simulate SCENE.json and report energy and momentum over time.");
    run->add_option("scene", scene_path, "Scene file (JSON)")->required();
    run->add_option("--csv", csv_path, "Write the time series to this CSV file");
    run->add_flag("--quiet,-q", quiet, "No summary; without --csv the CSV goes to standard output");

    auto* list = app.add_subcommand("responders", "List the responder names a scene may use.");

    CLI11_PARSE(app, argc, argv);
    try {
        if (*list) {
            for (auto name : responder_names()) fmt::print("{}\n", name);
            return 0;
        }
        return run_scene(scene_path, csv_path, quiet);
    } catch (const workbook::SceneError& error) {
        fmt::print(stderr, "error: {}\n", error.what());
        return 2;
    }
}
