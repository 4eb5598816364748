#pragma once
// The pile of chapter 5, the scene `./workbook bench pile` runs: N frictionless discs
// (spheres in z = 0) of radius 0.05 m and mass 1 kg, e = 0, dropped from a loose grid into a
// box of ground (y = 0) and two walls of inner width sqrt(N) x 0.1 m, g = 9.81 m/s^2 down,
// time step 1/60 s. Keeping its definition in one place makes the engines' numbers comparable:
// the workbook (pile.cpp) and each peer (pile_<engine>.cpp) build it from make_pile() and are
// measured by measure_pile().

#include <cstdint>
#include <ctime>
#include <limits>
#include <vector>

#include "workbook/contact_solver.hpp"

namespace workbook::bench {

struct Pile {
    static constexpr double radius = 0.05;         ///< m
    static constexpr double mass = 1.0;            ///< kg
    static constexpr double gravity = 9.81;        ///< m/s^2, along -y
    static constexpr double time_step = 1.0 / 60;  ///< s
    double width = 0.0;                            ///< inner width, m; the walls are at x = +-width/2
    std::vector<double> x, y;                      ///< start centres, m; at rest
    /// Height of the peers' walls, m: twice the highest start centre and a metre more (the
    /// workbook's walls are planes, endless upwards; no disc ever climbs above where it started).
    [[nodiscard]] double wall_height() const { return 2.0 * (y.empty() ? 0.0 : y.back()) + 1.0; }
};

/// The pile of `count` discs: rows of discs 2.4 radii apart (columns as many as fit the
/// width), the lowest a radius above the ground, each moved sideways by up to 0.1 radius
/// (the same pseudo-random numbers for every engine) so that the columns do not stay columns.
Pile make_pile(std::uint32_t count);

/// What one engine reports after running the pile.
struct PileResult {
    double seconds = 0.0;         ///< processor time of the steps, s
    double deepest = 0.0;         ///< deepest overlap of two discs or of a disc and the box at the end, m
    double kinetic = 0.0;         ///< kinetic energy at the end, J
    double mean_height = 0.0;     ///< mean height of the centres at the end, m
    std::uint32_t outside = 0;    ///< discs whose centre is not inside the box at the end
    bool over_budget = false;     ///< the run was stopped when its steps had taken `budget` s; no measurement
};

/// Runs `step` `steps` times, timing them with std::clock (processor time: every engine here
/// runs on one thread), and stops early once they have taken more than `budget` seconds, so
/// that an engine too slow at a large N is reported as over budget instead of holding the
/// bench for hours. Returns the seconds taken, or a negative number when over budget.
template <class Step>
double timed_steps(int steps, double budget, Step&& step) {
    const std::clock_t start = std::clock();
    auto elapsed = [start] { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; };
    for (int i = 0; i < steps; ++i) {
        step();
        if (i % 16 == 15 && elapsed() > budget) return -1.0;  // std::clock costs a system call: not every step
    }
    return elapsed();
}

/// No budget: run every step.
inline constexpr double unlimited = std::numeric_limits<double>::infinity();

/// Measures positions and velocities of discs at the end of a run, the same way for every engine.
PileResult measure_pile(const Pile& pile, const std::vector<double>& x, const std::vector<double>& y,
                        const std::vector<double>& vx, const std::vector<double>& vy);

/// The workbook's knobs for the pile (the defaults are what `resting-contact` scenes use).
struct PileKnobs {
    int velocity_iterations = 100;
    int position_iterations = 100;
    bool warm_start = true;
    double fraction = 0.5;  ///< share of the overlap beyond the slop removed per step
    double slop = 0.002;    ///< m
    bool swept = true;      ///< the swept test of fast spheres (WorldSettings::swept_spheres)
    double tolerance = 1e-9;  ///< m/s, ContactSolverSettings::tolerance
    int substeps = 0;         ///< ContactSolverSettings::substeps (0: one solve a step)
    double hertz = 30.0;      ///< ContactSolverSettings::contact_hertz
    bool sleeping = true;     ///< ContactSolverSettings::sleeping
    int relax_passes = ContactSolverSettings{}.relax_passes;  ///< ContactSolverSettings::relax_passes
    int shock_sweeps = ContactSolverSettings{}.shock_sweeps;     ///< ContactSolverSettings::shock_sweeps
    double shock_slope = ContactSolverSettings{}.shock_slope;    ///< ContactSolverSettings::shock_slope
    double speculative_distance = ContactSolverSettings{}.speculative_distance;  ///< m (0: off)
};

/// The workbook's other scheme on the pile: the soft step (ContactSolverSettings::substeps) at
/// the stiffest contact springs 16 substeps resolve (240 Hz) with one relax pass and a slop of
/// 0.4 mm, the setting docs/performance.md measures beside the defaults (a spring's give under
/// load comes on top of the slop, so the soft step keeps the slop small);
/// `workbook-pile workbook-soft N` runs it.
inline PileKnobs soft_step_knobs() {
    PileKnobs knobs;
    knobs.substeps = 16;
    knobs.hertz = 240.0;
    knobs.relax_passes = 1;
    knobs.slop = 0.0004;
    return knobs;
}

/// Runs the pile in the workbook with chapter 5's responder (the reference solution).
PileResult run_pile_workbook(const Pile& pile, int steps, const PileKnobs& knobs = {}, double budget = unlimited);

/// The pile in each peer, on the peer's own defaults (each file says which, and the little it
/// sets to make the scene the same: frictionless, e = 0, metres). Defined when the build found
/// the peer's Debian package (libchipmunk-dev, libbox2d-dev, libbullet-dev).
PileResult run_pile_chipmunk(const Pile& pile, int steps, double budget = unlimited);
PileResult run_pile_box2d(const Pile& pile, int steps, double budget = unlimited);
PileResult run_pile_bullet(const Pile& pile, int steps, double budget = unlimited);

/// The measurement of a peer's run: its discs' states measured, or over budget.
PileResult finish_pile(const Pile& pile, double seconds, const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& vx, const std::vector<double>& vy);

}  // namespace workbook::bench
