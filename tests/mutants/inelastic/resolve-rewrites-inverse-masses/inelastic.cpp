// Mutant of chapter 1 for the grader's tests: resolve also sets both inverse masses to that of the merged body, 1/(m1 + m2)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    const double merged = body1.inverse_mass * body2.inverse_mass / (body1.inverse_mass + body2.inverse_mass);
    if (!body1.is_immovable()) { body1.velocity = shared; body1.inverse_mass = merged; }
    if (!body2.is_immovable()) { body2.velocity = shared; body2.inverse_mass = merged; }
}

}  // namespace workbook::inelastic
