// Mutant of chapter 1 for the grader's tests: resolve() gives the common velocity to body 1 only
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    body1.velocity = common_velocity(body1, body2);  // body 2 forgotten
}

}  // namespace workbook::inelastic
