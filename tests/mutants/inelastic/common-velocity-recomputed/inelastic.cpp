// Mutant of chapter 1 for the grader's tests: resolve assigns body 1 first and then computes body 2's velocity again from the updated body 1
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    if (!body1.is_immovable()) body1.velocity = common_velocity(body1, body2);
    if (!body2.is_immovable()) body2.velocity = common_velocity(body1, body2);  // body 1 has already changed
}

}  // namespace workbook::inelastic
