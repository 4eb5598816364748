// workbook-accuracy: the stress corpus (numerical stability) and the accuracy bench (run time
// against error on the scene families that have a closed form).
#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ostream.h>

#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include <filesystem>
#include <stdexcept>

#include "bench.hpp"
#include "models.hpp"
#include "peers.hpp"
#include "stress.hpp"
#include "stress_table.hpp"
#include "workbook/response_model.hpp"

namespace {

using namespace workbook::accuracy;

const workbook::ResponseModel& model_named(const std::string& name) {
    try {
        return chapter_model(name.empty() ? default_stress_model : name);
    } catch (const std::invalid_argument& error) {
        throw CLI::ValidationError("--responder", error.what());
    }
}

int run_stress_command(bool full, const std::string& csv_path, const std::string& responder) {
    const workbook::ResponseModel& model = model_named(responder);
    fmt::print("stress corpus ({}), responder {}\n", full ? "full" : "small", model.name);
    std::vector<StressResult> results;
    for (const StressScene& scene : stress_corpus(full)) {
        fmt::print(stderr, "  {}: {}\n", scene.name, scene.what);
        results.push_back(run_stress(scene, model, [&scene](std::uint64_t done) {
            fmt::print(stderr, "\r  {} {:>9}/{} steps ({:3.0f}%)", scene.name, done, scene.steps,
                       100.0 * static_cast<double>(done) / static_cast<double>(scene.steps));
        }));
        fmt::print(stderr, "\n");
    }
    print_stress_table(std::cout, results);
    // Scene files the loader must refuse, naming the field, in about their reading time.
    fmt::print("\nrefused scenes (the loader must name the field)\n{:<18} {:>7}  {:<7}  {}\n", "scene", "time/s", "verdict",
               "message");
    bool refusals_pass = true;
    for (const RefusedScene& scene : refused_scenes()) {
        const RefusalResult r = check_refusal(scene);
        refusals_pass = refusals_pass && r.passed;
        const std::string message = r.message.size() > 110 ? r.message.substr(0, 107) + "..." : r.message;
        fmt::print("{:<18} {:>7.2f}  {:<7}  {}\n", r.scene, r.seconds, r.passed ? "pass" : "FAIL", message);
    }
    if (!refusals_pass) return 1;
    if (!csv_path.empty()) {
        std::ofstream out(csv_path);
        write_stress_csv(out, results);
        if (!out.flush()) {
            fmt::print(stderr, "error: cannot write {}\n", csv_path);
            return 1;
        }
    }
    for (const StressResult& r : results)
        if (!r.passed()) return 1;
    return 0;
}

bool write_file(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
    std::ofstream out(path);
    write(out);
    if (out.flush()) return true;
    fmt::print(stderr, "error: cannot write {}\n", path.string());
    return false;
}

int run_bench_command(const std::string& out_dir) {
    const std::filesystem::path dir(out_dir);
    std::filesystem::create_directories(dir);
    std::string peers;
    for (const PeerEngine& engine : peer_engines()) peers += (peers.empty() ? "" : ", ") + engine.name;
    fmt::print("accuracy bench; peers: {}\n", peers.empty() ? "none found (install libchipmunk-dev, libbox2d-dev, libbullet-dev)" : peers);
    std::string event_cost = "family,time_step,discrete_ns_per_step,event_ns_per_step,ratio\n";
    for (const Family& family : families()) {
        fmt::print(stderr, "  {} ({}) ...\n", family.id, family.model.name);
        std::vector<BenchPoint> points = sweep(family);
        if (peers_run(family.id))
            for (BenchPoint& p : peer_points(family.id)) points.push_back(std::move(p));
        // Named pareto-<family>: Doxygen copies every figure into one folder by its file name, and
        // chapter 3 has a scene figure called bouncing-ball too.
        if (!write_file(dir / ("pareto-" + family.id + ".csv"), [&](std::ostream& out) { write_bench_csv(out, points); }))
            return 1;
        double worst_ratio = 0.0;
        std::vector<EventCost> costs;
        if (family.contacts)
            for (int frames_per_second : frame_rates()) costs.push_back(measure_event_cost(family, 1.0 / frames_per_second));
        for (const EventCost& cost : costs) {
            event_cost += fmt::format("{},{:.17g},{:.4g},{:.4g},{:.4g}\n", family.id, cost.time_step,
                                      cost.discrete_ns_per_step, cost.event_ns_per_step, cost.ratio());
            worst_ratio = std::max(worst_ratio, cost.ratio());
        }
        const auto best = [&points](const std::string& engine, workbook::ContactTiming timing) {
            double e = 1e300;
            for (const BenchPoint& p : points)
                if (p.engine == engine && (engine != "workbook" || p.timing == timing)) e = std::min(e, p.result.error);
            return e;
        };
        std::string line = fmt::format("  {:<17} best error discrete {:.3g}", family.id,
                                       best("workbook", workbook::ContactTiming::discrete));
        if (family.contacts)
            line += fmt::format(", event {:.3g}; event / discrete per step <= {:.2f}",
                                best("workbook", workbook::ContactTiming::event), worst_ratio);
        if (peers_run(family.id))
            for (const PeerEngine& engine : peer_engines())
                line += fmt::format("; {} {:.3g}", engine.name, best(engine.name, workbook::ContactTiming::discrete));
        fmt::print("{}\n", line);
    }
    if (!write_file(dir / "event-cost.csv", [&](std::ostream& out) { out << event_cost; })) return 1;
    const workbook::ResponseModel& model = chapter_model(default_stress_model);
    std::string guard_csv = "scene,bodies,ns_per_step_on,ns_per_step_off,overhead_percent\n";
    for (const auto& [scene, steps] : {std::pair<std::string, int>{"steps-2e4", 200'000}, {"zero-gravity", 1'000}}) {
        const GuardCost guard = measure_guard_cost(model, scene, steps);
        const double overhead = 100.0 * (guard.on_ns / guard.off_ns - 1.0);
        fmt::print("  finite-state guard, {} ({} bodies): {:.0f} ns per step on, {:.0f} ns off ({:+.1f}%)\n", scene,
                   guard.bodies, guard.on_ns, guard.off_ns, overhead);
        guard_csv += fmt::format("{},{},{:.1f},{:.1f},{:.2f}\n", scene, guard.bodies, guard.on_ns, guard.off_ns, overhead);
    }
    return write_file(dir / "guard-cost.csv", [&](std::ostream& out) { out << guard_csv; }) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Stress corpus and accuracy bench of the Collision Response Workbook."};
    app.require_subcommand(1);

    bool full = false;
    std::string csv_path;
    std::string responder;
    auto* stress = app.add_subcommand("stress", "Run the stress corpus and print its table.");
    stress->add_flag("--full", full, "The full corpus (10,000 bodies, 10^6 steps; minutes) instead of the small one");
    stress->add_option("--csv", csv_path, "Also write the table as CSV here");
    stress->add_option("--responder", responder, "A response model by name (default: chapter 3's linear-impulse)");

    std::string out_dir = "accuracy";
    auto* bench = app.add_subcommand("bench", "Sweep time step, substeps, integrator and contact timing; write one CSV per family.");
    bench->add_option("--out", out_dir, "Folder for the CSV files");

    CLI11_PARSE(app, argc, argv);
    try {
        if (*stress) return run_stress_command(full, csv_path, responder);
        if (*bench) return run_bench_command(out_dir);
    } catch (const CLI::Error& error) {
        return app.exit(error);
    }
    return 0;
}
