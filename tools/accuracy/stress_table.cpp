#include "stress_table.hpp"

#include <fmt/core.h>
#include <fmt/ostream.h>

#include <ostream>

namespace workbook::accuracy {

namespace {

std::string verdict(const StressResult& r) { return r.passed() ? "pass" : "FAIL"; }

}  // namespace

void print_stress_table(std::ostream& out, const std::vector<StressResult>& results) {
    fmt::print(out, "{:<20} {:>9} {:>7} {:>24} {:>8} {:>7}\n", "scene", "steps", "bodies",
               "worst violation", "verdict", "time/s");
    for (const StressResult& r : results) {
        const std::string worst = r.error.empty() ? fmt::format("{:.3g} ({})", r.worst, r.worst_invariant) : "non-finite";
        fmt::print(out, "{:<20} {:>9} {:>7} {:>24} {:>8} {:>7.2f}\n", r.scene, r.steps, r.bodies, worst, verdict(r),
                   r.seconds);
        if (!r.error.empty()) fmt::print(out, "    {}\n", r.error);
    }
    fmt::print(out, "worst violation = measured / allowed (<= 1 passes); the bounds are in tools/accuracy/stress.hpp\n");
}

void write_stress_csv(std::ostream& out, const std::vector<StressResult>& results) {
    out << "scene,steps,bodies,worst_violation,worst_invariant,energy_ratio,momentum_ratio,box_ratio,box_escape_m,verdict,seconds\n";
    for (const StressResult& r : results)
        fmt::print(out, "{},{},{},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{},{:.6g}\n", r.scene, r.steps, r.bodies,
                   r.worst, r.worst_invariant, r.energy_ratio, r.momentum_ratio, r.box_ratio, r.box_escape, verdict(r),
                   r.seconds);
}

}  // namespace workbook::accuracy
