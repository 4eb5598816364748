// Mutant of chapter 3 for the grader's tests: resolve also takes away the tangential relative velocity (friction where there is none)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double j = impulse_magnitude(body1, body2, n, combined_restitution(body1, body2));
    body1.velocity += (j * body1.inverse_mass) * n;
    body2.velocity -= (j * body2.inverse_mass) * n;
    const Vector3 v12 = body1.velocity - body2.velocity;
    const Vector3 slip = v12 - dot(v12, n) * n;
    const double total = body1.inverse_mass + body2.inverse_mass;
    if (total > 0.0) {
        body1.velocity -= slip * (body1.inverse_mass / total);
        body2.velocity += slip * (body2.inverse_mass / total);
    }
}

}  // namespace workbook::linear_impulse
