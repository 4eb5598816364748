// workbook-pile [ENGINE] N [seconds] [velocity iterations] [position iterations] [warm start 0/1] [fraction] [slop]
//               [swept 0/1] [tolerance] [substeps] [contact hertz]
//               [sleeping 0/1] [relax passes] [shock sweeps] [shock slope] [speculative distance] [--budget SECONDS]
// runs the pile of pile.hpp in one engine (workbook, the default, chipmunk, box2d or bullet; the
// knobs after `seconds` are the workbook's), or in the workbook's soft step (workbook-soft:
// soft_step_knobs(), no knobs), and prints one CSV line:
//   engine,N,ms_per_step,deepest_m,kinetic_J,mean_height_m,outside
// or, when the steps took more than --budget seconds of processor time and were stopped,
//   engine,N,over budget,,,,
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "pile.hpp"

using namespace workbook::bench;

namespace {

/// The peer's run when this build has it (its Debian package was found), else nullptr.
using PeerRun = PileResult (*)(const Pile&, int, double);
PeerRun peer(std::string_view engine) {
#ifdef WORKBOOK_HAVE_CHIPMUNK
    if (engine == "chipmunk") return run_pile_chipmunk;
#endif
#ifdef WORKBOOK_HAVE_BOX2D
    if (engine == "box2d") return run_pile_box2d;
#endif
#ifdef WORKBOOK_HAVE_BULLET
    if (engine == "bullet") return run_pile_bullet;
#endif
    (void)engine;
    return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args;
    double budget = unlimited;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--budget") == 0 && i + 1 < argc)
            budget = std::stod(argv[++i]);
        else
            args.emplace_back(argv[i]);
    }
    std::string engine = "workbook";
    if (!args.empty() && !args.front().empty() && (args.front()[0] < '0' || args.front()[0] > '9')) {
        engine = args.front();
        args.erase(args.begin());
    }
    if (args.empty()) {
        std::fprintf(stderr, "usage: workbook-pile [workbook|workbook-soft|chipmunk|box2d|bullet] N [seconds] [velocity_iterations] "
                             "[position_iterations] [warm_start] [fraction] [slop] [swept] [tolerance] [substeps] [hertz] [sleeping] [relax passes] [shock sweeps] [shock slope] [speculative distance] [--budget SECONDS]\n");
        return 2;
    }
    const bool soft = engine == "workbook-soft";
    if (engine != "workbook" && !soft && peer(engine) == nullptr) {
        std::fprintf(stderr, "engine '%s' is unknown or was not built (its Debian package missing)\n", engine.c_str());
        return 2;
    }
    if (engine != "workbook" && args.size() > 2) {
        std::fprintf(stderr, "the knobs after `seconds` are the workbook's; %s runs on its own settings\n", engine.c_str());
        return 2;
    }
    try {
        const auto count = static_cast<std::uint32_t>(std::stoul(args[0]));
        const double seconds = args.size() > 1 ? std::stod(args[1]) : 10.0;
        PileKnobs knobs = soft ? soft_step_knobs() : PileKnobs{};
        if (args.size() > 2) knobs.velocity_iterations = std::stoi(args[2]);
        if (args.size() > 3) knobs.position_iterations = std::stoi(args[3]);
        if (args.size() > 4) knobs.warm_start = std::stoi(args[4]) != 0;
        if (args.size() > 5) knobs.fraction = std::stod(args[5]);
        if (args.size() > 6) knobs.slop = std::stod(args[6]);
        if (args.size() > 7) knobs.swept = std::stoi(args[7]) != 0;
        if (args.size() > 8) knobs.tolerance = std::stod(args[8]);
        if (args.size() > 9) knobs.substeps = std::stoi(args[9]);
        if (args.size() > 10) knobs.hertz = std::stod(args[10]);
        if (args.size() > 11) knobs.sleeping = std::stoi(args[11]) != 0;
        if (args.size() > 12) knobs.relax_passes = std::stoi(args[12]);
        if (args.size() > 13) knobs.shock_sweeps = std::stoi(args[13]);
        if (args.size() > 14) knobs.shock_slope = std::stod(args[14]);
        if (args.size() > 15) knobs.speculative_distance = std::stod(args[15]);
        const Pile pile = make_pile(count);
        const int steps = static_cast<int>(seconds / Pile::time_step + 0.5);
        const PileResult r = engine == "workbook" || soft ? run_pile_workbook(pile, steps, knobs, budget) : peer(engine)(pile, steps, budget);
        if (r.over_budget)
            std::printf("%s,%u,over budget,,,,\n", engine.c_str(), count);
        else
            std::printf("%s,%u,%.4g,%.4g,%.4g,%.4g,%u\n", engine.c_str(), count, steps > 0 ? 1e3 * r.seconds / steps : 0.0, r.deepest, r.kinetic,
                        r.mean_height, r.outside);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: %s\n", engine.c_str(), error.what());
        return 1;
    }
    return 0;
}
