// Mutant of chapter 1 for the grader's tests: the common velocity is the plain average of the two velocities, ignoring the masses
#include "inelastic.hpp"

namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    // Forgot the masses: the average of the velocities.
    return (body1.velocity + body2.velocity) / 2.0;
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    if (!body1.is_immovable()) body1.velocity = shared;
    if (!body2.is_immovable()) body2.velocity = shared;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
