// Event timing against discrete timing, per step, in the gas and in a pile, N = 1,000 to
// 100,000: the cost of answering each contact at its moment. Not a test (speed lives in
// benchmarks): `build/dev/bench/workbook-event-timing [N...]` prints a table. The goal is a
// ratio event / discrete under 2 at every N; docs/performance.md says where it stands and why.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "gas_world.hpp"
#include "state_hash.hpp"

namespace {

using namespace workbook;

/// The gas (bench/gas.hpp) with the given contact timing.
World gas(std::uint32_t count, ContactTiming timing) {
    World world = bench::make_gas_world(bench::make_gas(count));
    WorldSettings settings = world.settings();
    settings.contact_timing = timing;
    std::vector<RigidBody> bodies(world.bodies().begin(), world.bodies().end());
    return World(std::move(bodies), settings, world.model());
}

/// A pile: `count` balls of radius 0.05 m on a square lattice 0.11 m apart, dropped under
/// gravity onto a floor inside four walls, e = 0.5 (bench::elastic_impulse is e = 1; the
/// balls' restitution is what the bench's responder ignores, so the pile keeps bouncing as
/// the gas keeps flying: the same work every step). Run 30 steps before timing, so that the
/// lower layers already rest on each other.
World pile(std::uint32_t count, ContactTiming timing) {
    const auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(count / 10.0)));
    const double spacing = 0.11, r = 0.05;
    const double half = 0.5 * side * spacing + 0.01;
    std::vector<RigidBody> bodies;
    for (std::uint32_t n = 0; n < count; ++n) {
        const std::uint32_t x = n % side, z = (n / side) % side, y = n / (side * side);
        bodies.push_back(make_sphere(1.0, r, {-half + r + 0.005 + spacing * x, r + 0.001 + spacing * y, -half + r + 0.005 + spacing * z}));
    }
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, 0, 0}));
    bodies.push_back(make_immovable_plane({1, 0, 0}, {-half, 0, 0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {half, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 0, 1}, {0, 0, -half}));
    bodies.push_back(make_immovable_plane({0, 0, -1}, {0, 0, half}));
    static constexpr ResponseModel model{"elastic", bench::elastic_impulse, nullptr};
    WorldSettings settings{1.0 / 60.0, {0, -9.81, 0}};
    settings.contact_timing = timing;
    return World(std::move(bodies), settings, model);
}

/// CPU seconds per step over `steps` steps, after `warm` steps.
double per_step(World world, int warm, int steps) {
    world.set_shortcuts({.response_energy_probe = false});
    for (int i = 0; i < warm; ++i) world.step();
    const std::clock_t start = std::clock();
    for (int i = 0; i < steps; ++i) world.step();
    return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / steps;
}

}  // namespace

int main(int argc, char** argv) {
    // --hash: the state hash of the gas (discrete timing, as the speed bench runs it) after
    // every step, combined, at N = 1,000 (200 steps) and 10,000 (20 steps), then the same under
    // event timing for the gas and the pile: what a change that must not change results
    // compares before and after.
    if (argc > 1 && std::string(argv[1]) == "--hash") {
        for (const auto& [n, steps] : {std::pair{1000u, 200}, std::pair{10000u, 20}}) {
            World world = gas(n, ContactTiming::discrete);
            testing::StateHash h;
            for (int i = 0; i < steps; ++i) {
                world.step();
                h.add(testing::state_hash(world));
            }
            std::printf("gas N = %u, %d steps: %016llx\n", n, steps, static_cast<unsigned long long>(h.value()));
        }
        // And event timing's own results, gas and pile, which a change to its speed must keep.
        for (const bool is_gas : {true, false}) {
            for (const auto& [n, steps] : {std::pair{1000u, 60}, std::pair{10000u, 40}}) {
                World world = is_gas ? gas(n, ContactTiming::event) : pile(n, ContactTiming::event);
                testing::StateHash h;
                for (int i = 0; i < steps; ++i) {
                    world.step();
                    h.add(testing::state_hash(world));
                }
                std::printf("event timing, %s N = %u, %d steps: %016llx\n", is_gas ? "gas" : "pile", n, steps,
                            static_cast<unsigned long long>(h.value()));
            }
        }
        return 0;
    }
    // [gas|pile] N...: one scene only, at the given sizes.
    std::vector<std::string> scenes{"gas", "pile"};
    std::vector<std::uint32_t> counts;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "gas" || arg == "pile") scenes = {arg};
        else counts.push_back(static_cast<std::uint32_t>(std::strtoul(argv[i], nullptr, 10)));
    }
    if (counts.empty()) counts = {1'000, 10'000, 100'000};
    std::printf("%-6s %8s %14s %14s %7s\n", "scene", "N", "discrete ms", "event ms", "ratio");
    for (const std::string& scene : scenes) {
        for (const std::uint32_t n : counts) {
            const bool is_gas = scene == "gas";
            const int steps = n >= 100'000 ? 5 : 20;
            const int warm = is_gas ? 5 : 30;
            const auto build = [&](ContactTiming timing) { return is_gas ? gas(n, timing) : pile(n, timing); };
            const double discrete = per_step(build(ContactTiming::discrete), warm, steps);
            const double event = per_step(build(ContactTiming::event), warm, steps);
            std::printf("%-6s %8u %14.3f %14.3f %7.2f\n", scene.c_str(), n, 1e3 * discrete, 1e3 * event, event / discrete);
            std::fflush(stdout);
        }
    }
}
