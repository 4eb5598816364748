#include "pile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "workbook/probes.hpp"
#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

namespace workbook::bench {

Pile make_pile(std::uint32_t count) {
    Pile pile;
    pile.width = std::sqrt(static_cast<double>(count)) * 2.0 * Pile::radius;
    const double spacing = 2.4 * Pile::radius;
    const auto columns = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(pile.width / spacing));
    const double pitch = pile.width / columns;
    std::uint64_t state = 23;  // a fixed linear congruential sequence, the same everywhere
    for (std::uint32_t i = 0; i < count; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const double jitter = (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 0.2 * Pile::radius;
        const std::uint32_t column = i % columns, row = i / columns;
        pile.x.push_back(-pile.width / 2 + pitch * (column + 0.5) + jitter);
        pile.y.push_back(Pile::radius * 1.2 + spacing * row);
    }
    return pile;
}

PileResult measure_pile(const Pile& pile, const std::vector<double>& x, const std::vector<double>& y,
                        const std::vector<double>& vx, const std::vector<double>& vy) {
    PileResult r;
    const std::size_t n = x.size();
    const double h = pile.width / 2, d = 2 * Pile::radius;
    // Overlaps with the box, then between discs (sorted by x: only neighbours within 2r).
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) {
        order[i] = i;
        r.deepest = std::max({r.deepest, Pile::radius - y[i], x[i] + Pile::radius - h, -h - (x[i] - Pile::radius)});
        r.kinetic += 0.5 * Pile::mass * (vx[i] * vx[i] + vy[i] * vy[i]);
        r.mean_height += y[i] / static_cast<double>(n);
        if (!(x[i] > -h && x[i] < h && y[i] > 0.0)) ++r.outside;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n && x[order[b]] - x[order[a]] < d; ++b) {
            const double dx = x[order[b]] - x[order[a]], dy = y[order[b]] - y[order[a]];
            const double gap = std::sqrt(dx * dx + dy * dy);
            r.deepest = std::max(r.deepest, d - gap);
        }
    return r;
}

PileResult finish_pile(const Pile& pile, double seconds, const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& vx, const std::vector<double>& vy) {
    if (seconds < 0.0) {
        PileResult over;
        over.over_budget = true;
        return over;
    }
    PileResult result = measure_pile(pile, x, y, vx, vy);
    result.seconds = seconds;
    return result;
}

PileResult run_pile_workbook(const Pile& pile, int steps, const PileKnobs& knobs, double budget) {
    std::vector<RigidBody> bodies;
    for (std::size_t i = 0; i < pile.x.size(); ++i) {
        RigidBody disc = make_sphere(Pile::mass, Pile::radius, {pile.x[i], pile.y[i], 0});
        disc.restitution = 0.0;
        bodies.push_back(disc);
    }
    const double h = pile.width / 2;
    for (const auto& [normal, point] : {std::pair{Vector3{0, 1, 0}, Vector3{0, 0, 0}}, std::pair{Vector3{1, 0, 0}, Vector3{-h, 0, 0}},
                                        std::pair{Vector3{-1, 0, 0}, Vector3{h, 0, 0}}}) {
        RigidBody plane = make_immovable_plane(normal, point);
        plane.restitution = 0.0;
        bodies.push_back(plane);
    }
    const ResponseModel* model = find_response_model("resting-contact");
    if (model == nullptr)
        throw std::runtime_error("the pile needs the responder 'resting-contact' (chapter 5), which this build does not have");
    WorldSettings settings{Pile::time_step, {0, -Pile::gravity, 0}};
    settings.position_correction = {knobs.fraction, knobs.slop};
    settings.contact_solver.velocity_iterations = knobs.velocity_iterations;
    settings.contact_solver.position_iterations = knobs.position_iterations;
    settings.contact_solver.warm_start = knobs.warm_start;
    settings.swept_spheres = knobs.swept;
    settings.contact_solver.tolerance = knobs.tolerance;
    settings.contact_solver.substeps = knobs.substeps;
    settings.contact_solver.contact_hertz = knobs.hertz;
    settings.contact_solver.sleeping = knobs.sleeping;
    settings.contact_solver.relax_passes = knobs.relax_passes;
    settings.contact_solver.shock_sweeps = knobs.shock_sweeps;
    settings.contact_solver.shock_slope = knobs.shock_slope;
    settings.contact_solver.speculative_distance = knobs.speculative_distance;
    World world(std::move(bodies), settings, *model);
    world.set_shortcuts({.response_energy_probe = false});
    const double seconds = timed_steps(steps, budget, [&world] { world.step(); });
    std::vector<double> x, y, vx, vy;
    for (const RigidBody& b : world.bodies())
        if (!b.is_immovable()) {
            x.push_back(b.position.x);
            y.push_back(b.position.y);
            vx.push_back(b.velocity.x);
            vy.push_back(b.velocity.y);
        }
    return finish_pile(pile, seconds, x, y, vx, vy);
}

}  // namespace workbook::bench
