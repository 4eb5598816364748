// Mutant of chapter 1 for the grader's tests: resolve leaves a pair alone when |v1 - v2| < 1e-6 m/s (already moving together)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (length(body1.velocity - body2.velocity) < 1e-6) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    if (!body1.is_immovable()) body1.velocity = shared;
    if (!body2.is_immovable()) body2.velocity = shared;
}

}  // namespace workbook::inelastic
