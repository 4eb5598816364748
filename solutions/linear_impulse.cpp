// Reference solution for chapter 3, linear impulses with restitution.
#include "linear-impulse.hpp"

namespace workbook::linear_impulse {

double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal) {
    return dot(body1.velocity - body2.velocity, normal);
}

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    // Two immovable bodies: no impulse can change either velocity, and 0 avoids 0/0.
    if (inverse_mass_sum == 0.0) return 0.0;
    const double approach = relative_normal_velocity(body1, body2, normal);
    // |n|^2 turns the normal's length back out: J n is the same impulse for n and k n.
    return -(1.0 + restitution) * approach / (length_squared(normal) * inverse_mass_sum);
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    // A contact can only push: a pair that separates, slides or rests gets no impulse.
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double j = impulse_magnitude(body1, body2, n, combined_restitution(body1, body2));
    // Equal and opposite; inverse masses leave an immovable body exactly as it was (0 * J = 0).
    body1.velocity += (j * body1.inverse_mass) * n;
    body2.velocity -= (j * body2.inverse_mass) * n;
}

}  // namespace workbook::linear_impulse
