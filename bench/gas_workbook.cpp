// The gas in the workbook's own engine, with its own elastic impulse (gas_world.hpp says why).
#include <algorithm>
#include <ctime>

#include "gas_world.hpp"
#include "workbook/probes.hpp"
#include "workbook/world.hpp"

namespace workbook::bench {

void elastic_impulse(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const double approach = dot(body1.velocity - body2.velocity, contact.normal);
    const double inverse_masses = body1.inverse_mass + body2.inverse_mass;
    if (approach >= 0.0 || inverse_masses == 0.0) return;
    const double impulse = -2.0 * approach / inverse_masses;
    body1.velocity += contact.normal * (impulse * body1.inverse_mass);
    body2.velocity -= contact.normal * (impulse * body2.inverse_mass);
}

World make_gas_world(const Gas& gas) {
    std::vector<RigidBody> bodies;
    bodies.reserve(gas.discs.size() + 4);
    for (const Disc& d : gas.discs) bodies.push_back(make_sphere(Gas::mass, Gas::radius, {d.x, d.y, 0}, {d.vx, d.vy, 0}));
    const double h = gas.side / 2;
    bodies.push_back(make_immovable_plane({1, 0, 0}, {-h, 0, 0}));
    bodies.push_back(make_immovable_plane({-1, 0, 0}, {h, 0, 0}));
    bodies.push_back(make_immovable_plane({0, 1, 0}, {0, -h, 0}));
    bodies.push_back(make_immovable_plane({0, -1, 0}, {0, h, 0}));
    static constexpr ResponseModel model{"elastic", elastic_impulse, nullptr};
    return World(std::move(bodies), WorldSettings{Gas::time_step, {}}, model);
}

GasResult run_workbook(const Gas& gas, int steps) {
    World world = make_gas_world(gas);
    // Like the peers, the run records no per-response energy probe.
    world.set_shortcuts({.response_energy_probe = false});
    GasResult result;
    result.energy_before = measure(world.bodies(), {}).kinetic();
    const std::clock_t start = std::clock();
    for (int i = 0; i < steps; ++i) world.step();
    result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    result.energy_after = measure(world.bodies(), {}).kinetic();
    for (const RigidBody& body : world.bodies())
        if (!body.is_immovable() && !inside(gas, body.position.x, body.position.y)) ++result.escaped;
    return result;
}

}  // namespace workbook::bench
