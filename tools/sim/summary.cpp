#include "summary.hpp"

#include <fmt/ostream.h>

#include <ostream>

namespace workbook::sim {

void print_summary(std::ostream& out, const Scene& scene, const std::vector<Probes>& samples) {
    fmt::print(out, "{} ({} bodies, responder '{}', dt = {} s, {} steps)\n", scene.title, scene.bodies.size(),
               scene.responder, scene.settings.time_step, samples.size() - 1);
    const Probes& first = samples.front();
    const Probes& last = samples.back();
    fmt::print(out, "  total energy    {:.6f} J -> {:.6f} J\n", first.total_energy(), last.total_energy());
    fmt::print(out, "  linear momentum ({:.6f}, {:.6f}, {:.6f}) -> ({:.6f}, {:.6f}, {:.6f}) kg m/s\n",
               first.linear_momentum.x, first.linear_momentum.y, first.linear_momentum.z, last.linear_momentum.x,
               last.linear_momentum.y, last.linear_momentum.z);
    // A body resting on the ground is "hit" every step; list the first impacts and sum the rest.
    constexpr int listed = 5;
    int responses = 0;
    double unlisted_change = 0.0;
    for (const Probes& p : samples) {
        if (p.response_energy_change == 0.0) continue;
        if (++responses <= listed)
            fmt::print(out, "  impact at t = {:.4f} s: kinetic energy changed by {:.6f} J\n", p.time,
                       p.response_energy_change);
        else
            unlisted_change += p.response_energy_change;
    }
    if (responses > listed)
        fmt::print(out, "  ... and {} more steps with responses (resting contact), changing kinetic energy by {:.6g} J in all\n",
                   responses - listed, unlisted_change);
}

}  // namespace workbook::sim
