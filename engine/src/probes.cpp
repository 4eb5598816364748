#include "workbook/probes.hpp"

namespace workbook {

double kinetic_energy(const RigidBody& body) {
    if (body.is_immovable()) return 0.0;
    const double linear = 0.5 * body.mass() * length_squared(body.velocity);
    // A body that does not spin has no rotational energy: skip two matrix products.
    if (body.angular_velocity == Vector3{}) return linear;
    const double rotational = 0.5 * dot(body.angular_velocity, body.inertia_world() * body.angular_velocity);
    return linear + rotational;
}

Probes measure(std::span<const RigidBody> bodies, const Vector3& gravity, bool skip_still_rotation) {
    Probes p;
    for (const RigidBody& body : bodies) {
        if (body.is_immovable()) continue;
        const double m = body.mass();
        p.kinetic_linear += 0.5 * m * length_squared(body.velocity);
        p.potential -= m * dot(gravity, body.position);
        p.linear_momentum += m * body.velocity;
        if (skip_still_rotation && body.angular_velocity == Vector3{}) {
            // Adding the zero spin (+0 or -0 terms) would leave every sum's bits as they are.
            p.angular_momentum += cross(body.position, m * body.velocity);
            continue;
        }
        const Matrix3 inertia = body.inertia_world();
        const Vector3 spin = inertia * body.angular_velocity;
        p.kinetic_rotational += 0.5 * dot(body.angular_velocity, spin);
        p.angular_momentum += cross(body.position, m * body.velocity) + spin;
    }
    return p;
}

}  // namespace workbook
