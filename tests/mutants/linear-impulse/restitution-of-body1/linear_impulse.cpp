// Mutant of chapter 3 for the grader's tests: the pair's restitution is body 1's alone
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double j = impulse_magnitude(body1, body2, n, body1.restitution);
    body1.velocity += (j * body1.inverse_mass) * n;
    body2.velocity -= (j * body2.inverse_mass) * n;
}

}  // namespace workbook::linear_impulse
