// Google Benchmark micro benchmarks of each stage of World::step(), on the 2D gas (gas.hpp).
//   build/dev/bench/workbook-stages [--benchmark_filter=stage_in_step]
// A stage is timed inside whole steps: each iteration runs one step through the public stages
// in the order World::step() runs them (step_by_stages()), and only the chosen stage's time is
// counted. A stage called again and again on one state would time something else: detect()
// on its own gathers the broad phase's proxies itself (in a step integrate() gathers them on
// its pass) and, without this step's swept candidates, traces fast spheres against every body.
#include <benchmark/benchmark.h>

#include <chrono>
#include <utility>
#include <vector>

#include "gas_world.hpp"
#include "workbook/probes.hpp"

namespace {

using workbook::World;
using workbook::bench::make_gas;
using workbook::bench::make_gas_world;

World warm_gas(benchmark::State& state) {
    World world = make_gas_world(make_gas(static_cast<std::uint32_t>(state.range(0))));
    for (int i = 0; i < 10; ++i) world.step();
    return world;
}

/// A floor of 20 x 20 immovable tiles (boxes 0.5 m wide, edge to edge, so that neighbouring
/// tiles touch) under 400 falling balls: the scene where pairs of immovable bodies are many.
World tiled_floor() {
    std::vector<workbook::RigidBody> bodies;
    for (int i = 0; i < 400; ++i) {
        workbook::RigidBody tile = workbook::make_box(1.0, {0.25, 0.1, 0.25}, {-5.0 + 0.25 + 0.5 * (i % 20), -0.1, -5.0 + 0.25 + 0.5 * (i / 20)});
        tile.inverse_mass = 0.0;
        tile.inertia_body = workbook::Matrix3::zero();
        tile.update_world_inertia();
        bodies.push_back(tile);
    }
    for (int i = 0; i < 400; ++i)
        bodies.push_back(workbook::make_sphere(1.0, 0.1, {-4.75 + 0.5 * (i % 20), 0.5 + 0.1 * (i % 7), -4.75 + 0.5 * (i / 20)}));
    static constexpr workbook::ResponseModel model{"elastic", workbook::bench::elastic_impulse, nullptr};
    World world(std::move(bodies), workbook::WorldSettings{1.0 / 60.0, {0, -9.81, 0}}, model);
    for (int i = 0; i < 10; ++i) world.step();
    return world;
}

/// The stages of World::step(), in its order.
enum class Stage { integrate, detect, respond, correct, solve_contacts, keep_answered_impacts };

/// One step of `world` through its public stages, exactly as World::step() runs them (a test in
/// tests/engine/world.cpp holds step() to these calls), save the clock, which only step()
/// advances; returns the seconds `timed` took.
double step_by_stages(World& world, Stage timed) {
    double seconds = 0.0;
    const auto run = [&](Stage stage, auto&& call) {
        if (stage != timed) {
            call();
            return;
        }
        const auto start = std::chrono::steady_clock::now();
        call();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    if (world.settings().contact_timing == workbook::ContactTiming::event) {
        run(Stage::integrate, [&] { world.integrate_impact_to_impact(); });
        run(Stage::detect, [&] { world.detect(); });
        run(Stage::respond, [&] { world.respond(); });
        run(Stage::correct, [&] { world.correct(); });
        run(Stage::keep_answered_impacts, [&] { world.keep_answered_impacts(); });
        return seconds;
    }
    run(Stage::integrate, [&] { world.integrate(); });
    run(Stage::detect, [&] { world.detect(); });
    if (world.model().contact_solver != nullptr) {
        run(Stage::solve_contacts, [&] { world.solve_contacts(); });
    } else {
        run(Stage::respond, [&] { world.respond(); });
        run(Stage::correct, [&] { world.correct(); });
    }
    return seconds;
}

/// The gas of range(0) bodies with discrete (range 1 = 0) or event timing (1), warmed up.
World warm_gas_timed(benchmark::State& state) {
    const World warm = warm_gas(state);
    workbook::WorldSettings settings = warm.settings();
    settings.contact_timing = state.range(1) == 1 ? workbook::ContactTiming::event : workbook::ContactTiming::discrete;
    World world(std::vector<workbook::RigidBody>(warm.bodies().begin(), warm.bodies().end()), settings, warm.model());
    for (int i = 0; i < 5; ++i) world.step();
    return world;
}

/// One stage inside whole steps of the gas (integrate under event timing is
/// integrate_impact_to_impact(): moving from impact to impact, each answered there).
void stage_in_step(benchmark::State& state, Stage stage) {
    World world = warm_gas_timed(state);
    for (auto _ : state) state.SetIterationTime(step_by_stages(world, stage));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// detect() with the grid forced on (range 1 = 1) or every pair tested (0): where the two
/// cross is World's Shortcuts::broad_phase_from.
void detect_grid_or_all_pairs(benchmark::State& state) {
    World world = warm_gas(state);
    world.set_shortcuts({.broad_phase = state.range(1) == 1, .broad_phase_from = 0});
    for (auto _ : state) state.SetIterationTime(step_by_stages(world, Stage::detect));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// step() with one shortcut off (range 1: 0 none, 1 immovable pairs, 2 still rotation,
/// 3 zero gravity, 4 energy probe on, 5 broad phase): what each shortcut buys on the gas
/// (range 0 = its N) or, for range 0 = 0, on the tiled floor, where immovable pairs are many.
void step_with_one_shortcut_off(benchmark::State& state) {
    World world = state.range(0) == 0 ? tiled_floor() : warm_gas(state);
    workbook::Shortcuts shortcuts;
    shortcuts.response_energy_probe = false;  // what the gas driver runs with
    switch (state.range(1)) {
        case 1: shortcuts.skip_immovable_pairs = false; break;
        case 2: shortcuts.skip_still_rotation = false; break;
        case 3: shortcuts.skip_zero_gravity = false; break;
        case 4: shortcuts.response_energy_probe = true; break;
        case 5: shortcuts.broad_phase = false; break;
        default: break;
    }
    world.set_shortcuts(shortcuts);
    for (auto _ : state) {
        world.step();
        benchmark::DoNotOptimize(world.probes());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// step() of the gas with the swept test off (range 1 = 0) or on (1): what it costs.
void step_swept_or_not(benchmark::State& state) {
    const World warm = warm_gas(state);
    workbook::WorldSettings settings = warm.settings();
    settings.swept_spheres = state.range(1) == 1;
    World world(std::vector<workbook::RigidBody>(warm.bodies().begin(), warm.bodies().end()), settings, warm.model());
    world.set_shortcuts({.response_energy_probe = false});
    world.step();
    for (auto _ : state) world.step();
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void probes(benchmark::State& state) {
    World world = warm_gas(state);
    for (auto _ : state) benchmark::DoNotOptimize(world.probes());
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void step(benchmark::State& state) {
    World world = warm_gas(state);
    for (auto _ : state) world.step();
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

// Two bodies is where a broad phase may cost more than it saves; 1,000 and 10,000 are the gas.
// Range 0: N; range 1: 0 discrete timing, 1 event timing. A fixed count of steps: a stage
// the scene does not run (the gas has no position corrector) takes no time, and the library
// would run ever more steps to fill its minimum time.
BENCHMARK_CAPTURE(stage_in_step, integrate, Stage::integrate)->ArgsProduct({{2, 1000, 10000}, {0, 1}})->UseManualTime()->Iterations(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(stage_in_step, detect, Stage::detect)->ArgsProduct({{2, 1000, 10000}, {0, 1}})->UseManualTime()->Iterations(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(stage_in_step, respond, Stage::respond)->ArgsProduct({{2, 1000, 10000}, {0, 1}})->UseManualTime()->Iterations(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(stage_in_step, correct, Stage::correct)->ArgsProduct({{2, 1000, 10000}, {0, 1}})->UseManualTime()->Iterations(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(stage_in_step, keep_answered_impacts, Stage::keep_answered_impacts)->ArgsProduct({{2, 1000, 10000}, {0, 1}})->UseManualTime()->Iterations(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(detect_grid_or_all_pairs)->ArgsProduct({{2, 8, 16, 32, 64, 128}, {0, 1}})->UseManualTime();
BENCHMARK(step_with_one_shortcut_off)->ArgsProduct({{0, 1000}, {0, 1, 2, 3, 4, 5}})->Unit(benchmark::kMicrosecond);
BENCHMARK(step_swept_or_not)->ArgsProduct({{1000, 10000}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(probes)->Arg(2)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(step)->Arg(2)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
