// Mutant of chapter 2 for the grader's tests: correct also removes the approaching normal velocity (a velocity fix mixed into projection)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    const double inverse_mass_sum = w1 + w2;
    if (inverse_mass_sum == 0.0) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth <= 0.0) return;
    const Vector3 push = contact.normal * (depth / inverse_mass_sum);
    body1.position += push * w1;
    body2.position -= push * w2;
    const double approach = dot(body1.velocity - body2.velocity, contact.normal);
    if (approach < 0.0) {
        body1.velocity -= contact.normal * (approach * w1 / inverse_mass_sum);
        body2.velocity += contact.normal * (approach * w2 / inverse_mass_sum);
    }
}

}  // namespace workbook::projection
