// Mutant of chapter 1 for the grader's tests: resolve() merges only the velocity component along the normal
#include "inelastic.hpp"

namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0) return body1.velocity;
    if (w2 == 0.0) return body2.velocity;
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    const Vector3 n = contact.normal;
    const double v1n = dot(body1.velocity, n);
    const double v2n = dot(body2.velocity, n);
    if (v1n - v2n >= 0.0) return;
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    const double shared = (w2 * v1n + w1 * v2n) / (w1 + w2);
    body1.velocity += (shared - v1n) * n;  // the tangential part is left as it was
    body2.velocity += (shared - v2n) * n;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
