// workbook-pile N [seconds] [velocity iterations] [position iterations] [warm start 0/1] [fraction] [slop] [swept 0/1] [tolerance]:
// runs the pile of pile.hpp in the workbook and prints one CSV line:
// engine,N,ms_per_step,deepest_m,kinetic_J,mean_height_m,outside
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pile.hpp"

int main(int argc, char** argv) {
    using namespace workbook::bench;
    if (argc < 2) {
        std::fprintf(stderr, "usage: workbook-pile N [seconds] [velocity_iterations] [position_iterations] [warm_start] [fraction] [slop] [swept] [tolerance]\n");
        return 2;
    }
    const auto count = static_cast<std::uint32_t>(std::stoul(argv[1]));
    const double seconds = argc > 2 ? std::stod(argv[2]) : 10.0;
    PileKnobs knobs;
    if (argc > 3) knobs.velocity_iterations = std::stoi(argv[3]);
    if (argc > 4) knobs.position_iterations = std::stoi(argv[4]);
    if (argc > 5) knobs.warm_start = std::stoi(argv[5]) != 0;
    if (argc > 6) knobs.fraction = std::stod(argv[6]);
    if (argc > 7) knobs.slop = std::stod(argv[7]);
    if (argc > 8) knobs.swept = std::stoi(argv[8]) != 0;
    if (argc > 9) knobs.tolerance = std::stod(argv[9]);
    const Pile pile = make_pile(count);
    const int steps = static_cast<int>(seconds / Pile::time_step + 0.5);
    const PileResult r = run_pile_workbook(pile, steps, knobs);
    std::printf("workbook,%u,%.4g,%.4g,%.4g,%.4g,%u\n", count, 1e3 * r.seconds / steps, r.deepest, r.kinetic, r.mean_height,
                r.outside);
    return 0;
}
