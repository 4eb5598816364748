#pragma once
/// \file
/// The accuracy bench: run time against error over the choices that trade one for the other.

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "families.hpp"

namespace workbook::accuracy {

/// One configuration of the sweep and what it measured.
struct BenchPoint {
    std::string family;
    std::string engine = "workbook";  ///< or a peer's name and version (peers.hpp)
    double frame_step = 0.0;  ///< s, the step a game loop would call the world with
    int substeps = 1;         ///< world steps per frame; the world's time step is frame_step / substeps
    Integrator integrator = Integrator::semi_implicit_euler;
    ContactTiming timing = ContactTiming::discrete;
    FamilyError result;
    double seconds = 0.0;     ///< processor time of one run, s (the fastest of three batches' means)
    bool pareto = false;      ///< no faster point of the family has a smaller error
};

/// The frame steps of the sweep, in frames per second: 30, 60, ... 3840.
std::vector<int> frame_rates();

/// Frame steps 1/30 .. 1/3840 s, substeps 1, 2, 4 (world steps no finer than 1/3840 s), the
/// semi-implicit Euler and exact-under-gravity integrators (one of them when the family has no
/// gravity), discrete and event timing (discrete alone when it has no contact), with the
/// family's chapter model. The guard is off, as in every benchmark.
std::vector<BenchPoint> sweep(const Family& family);

/// Processor time of one call of `run`, s: batches of calls each lasting at least 10 ms of
/// processor time, the fastest batch's mean (shared with the peers' runs).
double seconds_per_run(const std::function<void()>& run);

/// Marks the Pareto front of the workbook's points of one family (peers' points are left
/// unmarked: the front shows what the workbook's choices reach).
void mark_pareto_front(std::vector<BenchPoint>& points);

/// The CSV the figures are drawn from, one line per point.
void write_bench_csv(std::ostream& out, const std::vector<BenchPoint>& points);

/// Names used in the CSV and on figures.
const char* integrator_name(Integrator integrator);
const char* timing_name(ContactTiming timing);

/// What the finite-state guard costs: ns per step with it on and off, over `steps` steps of the
/// small stress corpus's scene `scene_name`.
struct GuardCost {
    std::string scene;
    std::size_t bodies = 0;
    double on_ns = 0.0;
    double off_ns = 0.0;
};
GuardCost measure_guard_cost(const ResponseModel& model, const std::string& scene_name, int steps);

/// Event timing against discrete timing at the same world step, per step (a run's length
/// depends on what it measures: a stacked drop that launches the small ball too low ends
/// sooner), with the exact-under-gravity integrator.
struct EventCost {
    double time_step = 0.0;
    double discrete_ns_per_step = 0.0;
    double event_ns_per_step = 0.0;
    [[nodiscard]] double ratio() const { return event_ns_per_step / discrete_ns_per_step; }
};
/// Measured apart from the sweep, discrete and event runs alternating five times each and each
/// keeping its fastest, so that the load of a shared machine falls on both alike.
EventCost measure_event_cost(const Family& family, double time_step);

}  // namespace workbook::accuracy
