// workbook-gas ENGINE N STEPS: runs the 2D gas (gas.hpp) in one engine and prints one CSV line,
//   engine,n,steps,ms_per_step,energy_before,energy_after,relative_drift,escaped,peak_kb
// One process per run, so that each run's peak memory is its own.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <string_view>

#include "gas.hpp"

using namespace workbook::bench;

namespace {

/// The process's peak resident memory in kB, read from Linux's /proc/self/status (VmHWM);
/// -1 elsewhere. A parent's ru_maxrss cannot stand in: on Linux it includes the memory of
/// the forked parent before exec.
long peak_resident_kb() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            long kb = -1;
            status >> kb;
            return kb;
        }
        status.ignore(1 << 16, '\n');
    }
    return -1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s workbook|chipmunk|box2d|bullet N STEPS\n", argv[0]);
        return 2;
    }
    const std::string_view engine = argv[1];
    const long count = std::strtol(argv[2], nullptr, 10);
    const long steps = std::strtol(argv[3], nullptr, 10);
    if (count < 1 || steps < 0) {
        std::fprintf(stderr, "N must be positive and STEPS not negative\n");
        return 2;
    }
    GasResult (*run)(const Gas&, int) = nullptr;
    if (engine == "workbook") run = run_workbook;
#ifdef WORKBOOK_HAVE_CHIPMUNK
    if (engine == "chipmunk") run = run_chipmunk;
#endif
#ifdef WORKBOOK_HAVE_BOX2D
    if (engine == "box2d") run = run_box2d;
#endif
#ifdef WORKBOOK_HAVE_BULLET
    if (engine == "bullet") run = run_bullet;
#endif
    if (run == nullptr) {
        std::fprintf(stderr, "engine '%.*s' is unknown or was not built (its Debian package missing)\n",
                     static_cast<int>(engine.size()), engine.data());
        return 2;
    }
    try {
        const Gas gas = make_gas(static_cast<std::uint32_t>(count));
        const GasResult r = run(gas, static_cast<int>(steps));
        const double ms = steps > 0 ? 1e3 * r.seconds / static_cast<double>(steps) : 0.0;
        const double drift = std::abs(r.energy_after - r.energy_before) / r.energy_before;
        std::printf("%.*s,%ld,%ld,%.6g,%.17g,%.17g,%.3e,%u,%ld\n", static_cast<int>(engine.size()), engine.data(),
                    count, steps, ms, r.energy_before, r.energy_after, drift, r.escaped, peak_resident_kb());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%.*s at N = %ld failed: %s\n", static_cast<int>(engine.size()), engine.data(), count,
                     error.what());
        return 1;
    }
    return 0;
}
