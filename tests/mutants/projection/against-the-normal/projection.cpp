// Mutant of chapter 2 for the grader's tests: the normal is read as pointing from body 1 to body 2, so the bodies are pushed further into each other
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return;
    const Vector3 push = contact.normal * (depth_to_remove(contact.penetration, knobs) / (w1 + w2));
    body1.position -= push * w1;  // against the normal
    body2.position += push * w2;
}

}  // namespace workbook::projection
