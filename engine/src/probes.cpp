#include "workbook/probes.hpp"

namespace workbook {

double kinetic_energy(const RigidBody& body) {
    if (body.is_immovable()) return 0.0;
    const double linear = 0.5 * body.mass() * length_squared(body.velocity);
    const double rotational = 0.5 * dot(body.angular_velocity, body.inertia_world() * body.angular_velocity);
    return linear + rotational;
}

Probes measure(std::span<const RigidBody> bodies, const Vector3& gravity) {
    Probes p;
    for (const RigidBody& body : bodies) {
        if (body.is_immovable()) continue;
        const double m = body.mass();
        const Matrix3 inertia = body.inertia_world();
        const Vector3 spin = inertia * body.angular_velocity;
        p.kinetic_linear += 0.5 * m * length_squared(body.velocity);
        p.kinetic_rotational += 0.5 * dot(body.angular_velocity, spin);
        p.potential -= m * dot(gravity, body.position);
        p.linear_momentum += m * body.velocity;
        p.angular_momentum += cross(body.position, m * body.velocity) + spin;
    }
    return p;
}

}  // namespace workbook
