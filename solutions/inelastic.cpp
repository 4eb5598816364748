// Reference solution for chapter 1, perfectly inelastic collision.
#include "inelastic.hpp"

namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    // An immovable body imposes its own velocity; returning it directly keeps it exact,
    // where the general formula would add rounding (w1 v2 / w1 need not equal v2).
    if (w1 == 0.0) return body1.velocity;
    if (w2 == 0.0) return body2.velocity;
    // (m1 v1 + m2 v2) / (m1 + m2), multiplied through by w1 w2.
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    // A pair already flying apart along the normal is not colliding, whatever the overlap says.
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    if (!body1.is_immovable()) body1.velocity = shared;
    if (!body2.is_immovable()) body2.velocity = shared;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    const double reduced_mass = 1.0 / inverse_mass_sum;
    return 0.5 * reduced_mass * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
