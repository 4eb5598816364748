#pragma once
// The 2D gas, the one scene every engine in `./workbook bench speed` runs:
// N discs (spheres in z = 0) of radius 0.05 m and mass 1 kg in a square box of side
// L = 10 sqrt(N / 1000) m with four walls, velocities uniform in [-5, 5] m/s, e = 1, no
// gravity, time step 1/60 s, started on a grid. Keeping its definition in one place is what
// makes the peers' numbers comparable with the workbook's.

#include <cstdint>
#include <vector>

namespace workbook::bench {

struct Disc {
    double x, y;    ///< m
    double vx, vy;  ///< m/s
};

struct Gas {
    static constexpr double radius = 0.05;        ///< m
    static constexpr double mass = 1.0;           ///< kg
    static constexpr double time_step = 1.0 / 60; ///< s
    double side = 0.0;                            ///< L, m; the walls are at +-L/2
    std::vector<Disc> discs;
};

/// The gas of `count` discs; the same seed gives the same velocities on every engine.
Gas make_gas(std::uint32_t count, std::uint64_t seed = 12);

/// What one engine reports after running the gas.
struct GasResult {
    /// Processor time of the timed steps only (std::clock): every engine here runs on one
    /// thread, so on an idle machine this is the wall time, and on a shared one (2 cores, a
    /// load of 10 while others compile) it leaves out the time spent waiting for a core.
    double seconds = 0.0;
    double energy_before = 0.0;    ///< kinetic energy, J
    double energy_after = 0.0;     ///< J
    std::uint32_t escaped = 0;     ///< discs found outside the box at the end
};

/// Kinetic energy of discs of the gas's mass with the given speeds squared summed, J.
inline double kinetic(double speed_squared_sum) { return 0.5 * Gas::mass * speed_squared_sum; }

/// True when (x, y) lies inside the box, give or take 0.5 m: between two steps a disc may
/// overlap a wall by a step's travel (0.5 m is one step at 30 m/s) before the wall turns it
/// back; a disc that got through a wall flies on and leaves that margin for good.
inline bool inside(const Gas& gas, double x, double y) {
    const double h = gas.side / 2 + 0.5;
    return x > -h && x < h && y > -h && y < h;
}

/// The engines; each runs `steps` steps of `gas` and times them.
GasResult run_workbook(const Gas& gas, int steps);
GasResult run_chipmunk(const Gas& gas, int steps);
GasResult run_box2d(const Gas& gas, int steps);
GasResult run_bullet(const Gas& gas, int steps);

}  // namespace workbook::bench
