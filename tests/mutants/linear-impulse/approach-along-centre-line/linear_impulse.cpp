// Mutant of chapter 3 for the grader's tests: resolve decides whether the pair approaches along the line through the centres instead of contact.normal
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (dot(body1.velocity - body2.velocity, normalized(body1.position - body2.position)) >= 0.0) return;
    const double j = impulse_magnitude(body1, body2, n, combined_restitution(body1, body2));
    body1.velocity += (j * body1.inverse_mass) * n;
    body2.velocity -= (j * body2.inverse_mass) * n;
}

}  // namespace workbook::linear_impulse
