// Mutant of chapter 1 for the grader's tests: resolve gives both bodies the heavier body's velocity instead of the common one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = body1.inverse_mass <= body2.inverse_mass ? body1.velocity : body2.velocity;
    if (!body1.is_immovable()) body1.velocity = shared;
    if (!body2.is_immovable()) body2.velocity = shared;
}

}  // namespace workbook::inelastic
