// Mutant of chapter 2 for the grader's tests: the shares are written with masses, m2/(m1+m2) and m1/(m1+m2), which is right for two movable bodies but gives infinity over infinity (NaN) for an immovable one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double m1 = body1.mass();
    const double m2 = body2.mass();
    const double depth = depth_to_remove(contact.penetration, knobs);
    body1.position += contact.normal * (depth * m2 / (m1 + m2));
    body2.position -= contact.normal * (depth * m1 / (m1 + m2));
}

}  // namespace workbook::projection
