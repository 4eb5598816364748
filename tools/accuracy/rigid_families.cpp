// Chapter 4's families: a box that lands on one edge (the tilted rod) and a box that spins
// freely (torque-free rotation). See families.hpp for what each measures.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "families.hpp"
#include "workbook/time_series.hpp"

namespace workbook::accuracy {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

double TiltedRod::lever() const {
    const double theta = radians(tilt_degrees);
    return 0.5 * length * std::cos(theta) - 0.5 * thickness * std::sin(theta);
}

double TiltedRod::moment() const { return mass * (length * length + thickness * thickness) / 12.0; }

double TiltedRod::impulse() const {
    const double d = lever();
    return (1.0 + restitution) * impact_speed / (1.0 / mass + d * d / moment());
}

double TiltedRod::velocity_after() const { return -impact_speed + impulse() / mass; }

double TiltedRod::spin_after() const { return lever() * impulse() / moment(); }

World TiltedRod::world(WorldSettings settings, const ResponseModel& model) const {
    // Turned by +theta about z, the box's lower edge is the one at local (-L/2, -t/2): it lies
    // (L/2) sin(theta) + (t/2) cos(theta) below the centre.
    const double theta = radians(tilt_degrees);
    const double below = 0.5 * length * std::sin(theta) + 0.5 * thickness * std::cos(theta);
    const double drop = impact_speed * impact_speed / (2.0 * g);
    RigidBody box = make_box(mass, {0.5 * length, 0.5 * thickness, 0.5 * thickness}, {0.0, drop + below, 0.0},
                             from_axis_angle({0.0, 0.0, 1.0}, theta));
    box.restitution = restitution;
    RigidBody ground = make_immovable_plane({0.0, 1.0, 0.0}, {});
    ground.restitution = 1.0;
    settings.gravity = {0.0, -g, 0.0};
    return World({box, ground}, settings, model);
}

FamilyError tilted_rod_error(const WorldSettings& settings, const ResponseModel& model) {
    const TiltedRod rod;
    World world = rod.world(settings, model);
    FamilyError result;
    // The landing turns the box: the first step that leaves it spinning answered it. The edge
    // on the -x side goes up, so the spin about z is negative.
    while (world.time() < 2.0 * rod.time_of_impact() + 0.1) {
        world.step();
        const RigidBody& box = world.bodies()[0];
        if (box.angular_velocity == Vector3{}) continue;
        const double t_since = world.time() - rod.time_of_impact();
        const double v_exact = rod.velocity_after() - rod.g * t_since;
        const double dv = length(box.velocity - Vector3{0.0, v_exact, 0.0});
        const double dw = length(box.angular_velocity - Vector3{0.0, 0.0, -rod.spin_after()});
        result.error = std::max(dv, dw * rod.lever()) / rod.impact_speed;
        break;
    }
    result.steps = world.steps_taken();
    return result;
}

FamilyError torque_free_box_error(const WorldSettings& settings, const ResponseModel& model) {
    RigidBody box = make_box(1.0, {0.5, 0.25, 0.1}, {});
    box.angular_velocity = {0.01, 4.0, 0.01};
    WorldSettings free = settings;
    free.gravity = {};
    World world({box}, free, model);
    // The world-frame L, not only its length: a box turned about a fixed w (no precession)
    // keeps |L| and E too, but not the direction of L.
    const auto momentum_and_energy = [&world] {
        const RigidBody& b = world.bodies()[0];
        const Vector3 l = b.inertia_world() * b.angular_velocity;
        return std::pair{l, 0.5 * dot(b.angular_velocity, l)};
    };
    const auto [l0, e0] = momentum_and_energy();
    FamilyError result;
    result.error = 0.0;
    result.steps = step_count(10.0, settings.time_step);
    for (std::size_t n = 0; n < result.steps; ++n) {
        world.step();
        const auto [l, e] = momentum_and_energy();
        result.error = std::max({result.error, length(l - l0) / length(l0), std::abs(e - e0) / e0});
    }
    return result;
}

}  // namespace workbook::accuracy
