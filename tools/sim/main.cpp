// workbook-sim: runs a scene file with the linked responders and writes its probes.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "summary.hpp"
#include "trajectory.hpp"
#include "workbook/guards.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace {

std::vector<std::string_view> responder_names() {
    std::vector<std::string_view> names;
    for (const auto& model : workbook::response_models()) names.push_back(model.name);
    return names;
}

/// Set by Ctrl-C (SIGINT): the run stops after the current step and keeps what it has.
volatile std::sig_atomic_t interrupted = 0;

/// The guard's message when the world stopped on a NaN or an infinity (workbook/guards.hpp).
std::string stopped_by;

extern "C" void on_interrupt(int) { interrupted = 1; }

/// Steps the world for the scene's duration like workbook::run, with two things a person at
/// a terminal needs: a progress line on standard error once a run has taken two seconds,
/// and Ctrl-C, which ends the run after the current step with the samples so far.
std::vector<workbook::Probes> run_with_progress(workbook::World& world, double duration) {
    using clock = std::chrono::steady_clock;
    const std::size_t steps = workbook::step_count(duration, world.settings().time_step);
    std::vector<workbook::Probes> samples;
    samples.reserve(steps + 1);
    samples.push_back(world.probes());
    const auto start = clock::now();
    auto last_report = start;
    bool reported = false;
    interrupted = 0;
    const auto previous = std::signal(SIGINT, on_interrupt);
    for (std::size_t i = 1; i <= steps && interrupted == 0; ++i) {
        try {
            world.step();
        } catch (const workbook::NonFiniteState& error) {
            // Keep what was finite and the first sample that is not, so a figure can show
            // where the values stopped being finite; the message says which body and stage.
            samples.push_back(world.probes());
            stopped_by = error.what();
            break;
        }
        samples.push_back(world.probes());
        const auto now = clock::now();
        const double elapsed = std::chrono::duration<double>(now - start).count();
        if (elapsed < 2.0 || now - last_report < std::chrono::milliseconds(500)) continue;
        last_report = now;
        reported = true;
        const double left = elapsed * static_cast<double>(steps - i) / static_cast<double>(i);
        fmt::print(stderr, "\r  step {} of {} ({:.0f}%), t = {:.3f} s, {:.0f} s so far, about {:.0f} s left (Ctrl-C stops and keeps the CSV)  ",
                   i, steps, 100.0 * static_cast<double>(i) / static_cast<double>(steps), world.time(), elapsed, left);
        std::fflush(stderr);
    }
    std::signal(SIGINT, previous == SIG_ERR ? SIG_DFL : previous);
    if (reported) fmt::print(stderr, "\n");
    if (interrupted != 0)
        fmt::print(stderr, "interrupted at t = {:.4f} s after {} of {} steps; keeping those\n", world.time(),
                   samples.size() - 1, steps);
    return samples;
}

/// Prints which stages the scene's world uses and which it skips, with the reasons.
void explain(const workbook::Scene& scene, const workbook::World& world) {
    fmt::print("{} ({} bodies)\n", scene.title, scene.bodies.size());
    for (const workbook::StageUse& use : world.plan())
        fmt::print("  {:<36} {:<7} {}\n", use.stage, use.used ? "used" : "skipped", use.why);
}

/// How a run ends, as its exit status (the front end maps each to its own message; see the
/// help's footer). A crash is none of these: the process is killed by a signal, which a shell
/// shows as 128 + the signal's number and Python's subprocess as minus that number.
enum Exit : int {
    exit_ran = 0,             ///< ran to the end of the scene
    exit_output_failed = 1,   ///< could not write an output file
    exit_refused = 2,         ///< the scene or the command line was refused; the message names file, field, problem
    exit_not_finite = 3,      ///< the guard stopped the run at a NaN or an infinity; samples up to there are written
    exit_internal_error = 4,  ///< an exception the simulator did not expect (a bug: please report it)
    exit_interrupted = 130,   ///< Ctrl-C: 128 + SIGINT, as a shell reports it; samples so far are written
};

constexpr const char* exit_codes_help =
    "Exit status: 0 ran to the end; 1 an output file could not be written; 2 the scene or command line was "
    "refused (the message names the file, the field and the problem); 3 stopped at a NaN or an infinity (the "
    "samples up to there are written); 4 internal error; 130 interrupted by Ctrl-C. A crash is none of these: "
    "the process is killed by a signal (a shell shows 128 + its number).";

int run_scene(const std::string& scene_path, const std::string& csv_path, bool quiet, bool explain_only,
              const std::string& trajectory_path, std::size_t stride) {
    const auto names = responder_names();
    const workbook::Scene scene = workbook::load_scene(scene_path, names);
    const workbook::ResponseModel& model = *workbook::find_response_model(scene.responder);
    if (explain_only) {
        explain(scene, workbook::make_world(scene, model));
        return 0;
    }
    std::vector<workbook::Probes> samples;
    if (trajectory_path.empty()) {
        workbook::World world = workbook::make_world(scene, model);
        samples = run_with_progress(world, scene.duration);
    } else {
        // Recording a trajectory steps the same world with a recorder around the responder
        // (tools/sim/trajectory.cpp); it has no progress line.
        auto simulated = workbook::sim::simulate(scene, trajectory_path, stride);
        if (!simulated) return exit_output_failed;
        samples = std::move(*simulated);
    }

    if (!csv_path.empty()) {
        std::ofstream out(csv_path);
        if (!out) {
            fmt::print(stderr, "error: cannot write {}\n", csv_path);
            return exit_output_failed;
        }
        workbook::write_csv(out, samples);
        if (!out.flush()) {
            fmt::print(stderr, "error: writing {} failed\n", csv_path);
            return exit_output_failed;
        }
    } else if (quiet) {
        workbook::write_csv(std::cout, samples);
    }
    if (!quiet) workbook::sim::print_summary(std::cout, scene, samples);
    if (!stopped_by.empty()) {
        fmt::print(stderr, "stopped: {}\n", stopped_by);
        return exit_not_finite;
    }
    // 128 + SIGINT, as a shell reports a run stopped by Ctrl-C.
    return interrupted != 0 ? exit_interrupted : exit_ran;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Runs collision-response scenes of the Collision Response Workbook."};
    app.require_subcommand(1);

    std::string scene_path;
    std::string csv_path;
    bool quiet = false;
    bool explain_only = false;
    auto* run = app.add_subcommand("run", "Simulate SCENE.json and report energy and momentum over time.");
    run->add_option("scene", scene_path, "Scene file (JSON)")->required();
    run->add_option("--csv", csv_path, "Write the time series to this CSV file");
    run->add_flag("--quiet,-q", quiet, "No summary; without --csv the CSV goes to standard output");
    run->add_flag("--explain", explain_only, "List the stages the scene uses and those it skips, and why; do not run");
    std::string trajectory_path;
    std::size_t stride = 1;
    run->add_option("--trajectory", trajectory_path,
                    "Write every body's state per recorded frame to this CSV, and the contacts to *.contacts.csv");
    run->add_option("--stride", stride, "With --trajectory: record every K-th step (and always the first and last)")
        ->check(CLI::PositiveNumber);

    auto* list = app.add_subcommand("responders", "List the responder names a scene may use.");

    app.footer(exit_codes_help);
    run->footer(exit_codes_help);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help is a ParseError too, with exit code 0; every real one is a refusal.
        const int status = app.exit(error);
        return status == 0 ? exit_ran : exit_refused;
    }
    try {
        if (*list) {
            for (auto name : responder_names()) fmt::print("{}\n", name);
            return 0;
        }
        return run_scene(scene_path, csv_path, quiet, explain_only, trajectory_path, stride);
    } catch (const workbook::SceneError& error) {
        fmt::print(stderr, "error: {}\n", error.what());
        return exit_refused;
    } catch (const workbook::NonFiniteState& error) {
        fmt::print(stderr, "stopped: {}\n", error.what());
        return exit_not_finite;
    } catch (const std::exception& error) {
        fmt::print(stderr, "internal error: {}\n", error.what());
        return exit_internal_error;
    }
}
