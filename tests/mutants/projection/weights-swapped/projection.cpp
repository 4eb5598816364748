// Mutant of chapter 2 for the grader's tests: each body moves by its own share of the mass instead of the other's, so the heavy body moves further
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return;
    const Vector3 push = contact.normal * (depth_to_remove(contact.penetration, knobs) / (w1 + w2));
    body1.position += push * w2;  // weights swapped
    body2.position -= push * w1;
}

}  // namespace workbook::projection
