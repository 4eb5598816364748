#include "workbook/time_series.hpp"

#include <cmath>
#include <limits>
#include <ostream>

namespace workbook {

std::size_t step_count(double duration, double time_step) {
    return static_cast<std::size_t>(std::llround(duration / time_step));
}

std::vector<Probes> run(World& world, double duration) {
    const std::size_t steps = step_count(duration, world.settings().time_step);
    std::vector<Probes> samples;
    samples.reserve(steps + 1);
    samples.push_back(world.probes());
    for (std::size_t i = 0; i < steps; ++i) {
        world.step();
        samples.push_back(world.probes());
    }
    return samples;
}

const char* csv_header() {
    return "t,kinetic_linear,kinetic_rotational,potential,total,"
           "momentum_x,momentum_y,momentum_z,angular_momentum_x,angular_momentum_y,angular_momentum_z,"
           "response_energy_change,contacts,penetration_max";
}

void write_csv(std::ostream& out, const std::vector<Probes>& samples) {
    // Shortest form at round-trip precision, whatever format the caller left on the stream.
    const auto old_flags = out.flags();
    const auto old_precision = out.precision(std::numeric_limits<double>::max_digits10);
    out.unsetf(std::ios::floatfield);
    out << csv_header() << '\n';
    for (const Probes& p : samples) {
        out << p.time << ',' << p.kinetic_linear << ',' << p.kinetic_rotational << ',' << p.potential << ','
            << p.total_energy() << ',' << p.linear_momentum.x << ',' << p.linear_momentum.y << ','
            << p.linear_momentum.z << ',' << p.angular_momentum.x << ',' << p.angular_momentum.y << ','
            << p.angular_momentum.z << ',' << p.response_energy_change << ',' << p.contacts << ',' << p.penetration_max << '\n';
    }
    out.precision(old_precision);
    out.flags(old_flags);
}

}  // namespace workbook
