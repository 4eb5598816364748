// Mutant of chapter 2 for the grader's tests: the slop is taken off the depth before calling depth_to_remove, which takes it off again
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return;
    const double depth = depth_to_remove(contact.penetration - knobs.slop, knobs);  // slop twice
    const Vector3 push = contact.normal * (depth / (w1 + w2));
    body1.position += push * w1;
    body2.position -= push * w2;
}

}  // namespace workbook::projection
