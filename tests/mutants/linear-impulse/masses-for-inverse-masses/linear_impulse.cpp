// Mutant of chapter 3 for the grader's tests: the impulse is multiplied by the masses where the inverse masses belong
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double j = impulse_magnitude(body1, body2, n, combined_restitution(body1, body2));
    if (!body1.is_immovable()) body1.velocity += (j * body1.mass()) * n;  // J m instead of J / m
    if (!body2.is_immovable()) body2.velocity -= (j * body2.mass()) * n;
}

}  // namespace workbook::linear_impulse
