// Mutant of chapter 1 for the grader's tests: stuck bodies are also stopped spinning: resolve sets both angular velocities to zero
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    if (!body1.is_immovable()) { body1.velocity = shared; body1.angular_velocity = Vector3{}; }
    if (!body2.is_immovable()) { body2.velocity = shared; body2.angular_velocity = Vector3{}; }
}

}  // namespace workbook::inelastic
