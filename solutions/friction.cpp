// Reference solution for chapter 6, friction.
#include "friction.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace workbook::friction {

// The solver calls these in its inner loop: they read the world inverse inertia the world
// keeps current (RigidBody::inverse_inertia_world), as chapter 5's reference does.
namespace {

Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    return body.velocity + cross(body.angular_velocity, point - body.position);
}

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += body1.inverse_inertia_world * cross(point - body1.position, impulse);
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity -= body2.inverse_inertia_world * cross(point - body2.position, impulse);
}

}  // namespace

double mix_coefficients(double mu1, double mu2) {
    // The geometric mean: mix(mu, mu) = mu, mix(0, mu) = 0, and never above the larger one.
    return std::sqrt(mu1 * mu2);
}

std::array<Vector3, 2> tangent_basis(const Vector3& normal) {
    // Cross the normal with the world axis it is least aligned with: that axis makes an angle
    // of at least about 55 degrees with the normal, so the cross product is never short and
    // its normalisation never divides by (nearly) zero. A fixed axis fails on a normal along it.
    const double ax = std::abs(normal.x), ay = std::abs(normal.y), az = std::abs(normal.z);
    const Vector3 axis = ax <= ay && ax <= az ? Vector3{1, 0, 0} : ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
    const Vector3 t1 = normalized(cross(normal, axis));
    return {t1, cross(normal, t1)};
}

double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    // Chapter 4's denominator with the tangent for the normal. The angular terms matter far
    // more here: a ball's lever arm lies along the normal (no angular term there) but across
    // every tangent.
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(body1.inverse_inertia_world * cross(r1, tangent), r1);
    const Vector3 turn2 = cross(body2.inverse_inertia_world * cross(r2, tangent), r2);
    const double k = body1.inverse_mass + body2.inverse_mass + dot(tangent, turn1 + turn2);
    return k > 0.0 ? 1.0 / k : 0.0;
}

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    // Clamp the running sum against the running normal sum, not this pass's increments: a
    // later pass may take back friction an earlier one gave, as chapter 5's normal impulses.
    const std::array<double, 2> before = accumulated;
    accumulated[0] += increment[0];
    accumulated[1] += increment[1];
    const double size = std::hypot(accumulated[0], accumulated[1]);
    if (!(size <= static_coefficient * normal_impulse)) {
        // Sliding: the full dynamic friction, along the impulse that would have stopped the
        // slip. size > 0 here (size > mu_s J_n >= 0), so the division is safe.
        const double scale = dynamic_coefficient * normal_impulse / size;
        accumulated[0] *= scale;
        accumulated[1] *= scale;
    }
    return {accumulated[0] - before[0], accumulated[1] - before[1]};
}

double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    const double static_coefficient = mix_coefficients(body1.static_friction, body2.static_friction);
    const double dynamic_coefficient = mix_coefficients(body1.friction, body2.friction);
    const std::array<Vector3, 2> t = tangent_basis(contact.normal);
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        const Vector3& at = contact.points[i].position;
        const Vector3 slip = point_velocity(body1, at) - point_velocity(body2, at);
        std::array<double, 2> increment{};
        for (std::size_t d = 0; d < 2; ++d) increment[d] = -tangent_mass(body1, body2, at, t[d]) * dot(slip, t[d]);
        const std::array<double, 2> applied =
            accumulate_friction(p.friction, increment, p.normal, static_coefficient, dynamic_coefficient);
        const Vector3 impulse = applied[0] * t[0] + applied[1] * t[1];
        if (impulse == Vector3{}) continue;
        apply_impulse(body1, body2, at, impulse);
        const Vector3 change = point_velocity(body1, at) - point_velocity(body2, at) - slip;
        largest = std::max(largest, length(change - dot(change, contact.normal) * contact.normal));
    }
    return largest;
}

}  // namespace workbook::friction
