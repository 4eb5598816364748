#pragma once
// Bodies and measurements shared by chapter 4's public and hidden step tests. Nothing here
// resolves a contact: it builds the cases and measures the laws.
#include <cmath>
#include <numbers>
#include <string>

#include "feedback.hpp"
#include "workbook/contact.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::angular_impulse_cases {

/// A thin rod of mass m and length L along its body x axis, tilted by `theta` (rad) out of
/// the ground plane (z up) about the y axis, its centre at `centre`. Its moment about any
/// axis across it is m L^2 / 12; about its own axis a small positive one.
inline RigidBody thin_rod(double mass, double length, double theta, const Vector3& centre, const Vector3& velocity) {
    RigidBody rod;
    rod.inverse_mass = 1.0 / mass;
    const double across = mass * length * length / 12.0;
    rod.inertia_body = Matrix3::diagonal({1e-4 * across, across, across});
    rod.position = centre;
    rod.orientation = from_axis_angle({0, 1, 0}, -theta);  // body x goes to (cos theta, 0, sin theta)
    rod.velocity = velocity;
    rod.restitution = 1.0;
    rod.shape = Shape::box({length / 2.0, 0.01 * length, 0.01 * length});
    rod.update_world_inertia();
    return rod;
}

/// The lower end of a thin_rod().
inline Vector3 rod_lower_end(const RigidBody& rod, double length) {
    return rod.position - rotate(rod.orientation, Vector3{length / 2.0, 0, 0});
}

/// The ground: an immovable plane z = 0 whose normal is +z.
inline RigidBody ground() { return make_immovable_plane({0, 0, 1}, {0, 0, 0}); }

/// A contact with `normal` (from body 2 to body 1) at the given points.
template <typename... Points>
Contact contact_at(const Vector3& normal, const Points&... points) {
    Contact c;
    c.normal = normal;
    (c.add_point(points, 0.001), ...);
    return c;
}

/// The velocity of the material point at `p`, from the engine's fields (the law, not the step).
inline Vector3 velocity_at(const RigidBody& b, const Vector3& p) { return b.velocity + cross(b.angular_velocity, p - b.position); }

/// u = (v_p1 - v_p2) . n at p.
inline double normal_velocity_at(const RigidBody& b1, const RigidBody& b2, const Vector3& p, const Vector3& n) {
    return dot(velocity_at(b1, p) - velocity_at(b2, p), n);
}

/// Linear momentum of the movable bodies.
inline Vector3 momentum(const RigidBody& a, const RigidBody& b) {
    Vector3 sum{};
    if (!a.is_immovable()) sum += a.mass() * a.velocity;
    if (!b.is_immovable()) sum += b.mass() * b.velocity;
    return sum;
}

/// Angular momentum about the origin, x cross m v + I w, of the movable bodies.
inline Vector3 angular_momentum(const RigidBody& a, const RigidBody& b) {
    Vector3 sum{};
    for (const RigidBody* body : {&a, &b})
        if (!body->is_immovable())
            sum += cross(body->position, body->mass() * body->velocity) + body->inertia_world() * body->angular_velocity;
    return sum;
}

/// 1/2 m v^2 + 1/2 w . I w of one movable body.
inline double kinetic(const RigidBody& b) {
    if (b.is_immovable()) return 0.0;
    return 0.5 * b.mass() * length_squared(b.velocity) + 0.5 * dot(b.angular_velocity, b.inertia_world() * b.angular_velocity);
}

/// "m = 2 kg, v = ..., w = ... rad/s, at ..." for the case part of a message.
inline std::string describe_body(const RigidBody& b) {
    using workbook::testing::format;
    if (b.is_immovable())
        return "immovable, v = " + format(b.velocity) + " m/s, w = " + format(b.angular_velocity) + " rad/s";
    return "m = " + format(b.mass()) + " kg at " + format(b.position) + " m, v = " + format(b.velocity) + " m/s, w = " +
           format(b.angular_velocity) + " rad/s, I_body diagonal " +
           format(Vector3{b.inertia_body(0, 0), b.inertia_body(1, 1), b.inertia_body(2, 2)}) + " kg m^2, orientation (" +
           format(b.orientation.w) + "; " + format(Vector3{b.orientation.x, b.orientation.y, b.orientation.z}) + ")";
}

inline std::string pair_text(const RigidBody& a, const RigidBody& b) {
    return "body 1: " + describe_body(a) + "; body 2: " + describe_body(b);
}

/// A movable box with random mass (over two decades), size, orientation, velocity and spin.
template <typename Random>
RigidBody random_box(Random& random, const Vector3& centre) {
    const Vector3 half{random.uniform(0.1, 1.0), random.uniform(0.1, 1.0), random.uniform(0.1, 1.0)};
    // One draw a statement: the order in which a call's arguments are evaluated is up to the
    // compiler (GCC goes right to left, Clang left to right), and the cases must be the same
    // on every compiler. This is the order GCC drew them in when they were arguments.
    const Vector3 velocity = random.vector(3.0);
    const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
    const Vector3 axis = random.direction();
    const double mass = random.log_uniform(-1, 1);
    RigidBody box = make_box(mass, half, centre, from_axis_angle(axis, angle), velocity);
    box.angular_velocity = random.vector(4.0);
    box.update_world_inertia();
    return box;
}

}  // namespace workbook::angular_impulse_cases
