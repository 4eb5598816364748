#include "gas.hpp"

#include <cmath>
#include <random>

namespace workbook::bench {

Gas make_gas(std::uint32_t count, std::uint64_t seed) {
    Gas gas;
    gas.side = 10.0 * std::sqrt(count / 1000.0);
    // Rows of k discs, k = ceil(sqrt(N)), evenly spaced: at every N the spacing (L / k,
    // about 0.32 m) is larger than a diameter, so no two discs start overlapping.
    const auto k = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    const double spacing = gas.side / k;
    std::mt19937_64 engine(seed);
    // mt19937_64's output is fixed by the standard; the distributions are not, so map by hand.
    auto speed = [&engine] { return -5.0 + 10.0 * (static_cast<double>(engine() >> 11) * 0x1.0p-53); };
    gas.discs.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const double x = (i % k + 0.5) * spacing - gas.side / 2;
        const double y = (i / k + 0.5) * spacing - gas.side / 2;
        const double vx = speed();
        const double vy = speed();
        gas.discs.push_back({x, y, vx, vy});
    }
    return gas;
}

}  // namespace workbook::bench
