// Mutant of chapter 2 for the grader's tests: correct normalises the two inverse masses to shares that add up to 1 and stores them
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double total = body1.inverse_mass + body2.inverse_mass;
    if (total == 0.0) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth <= 0.0) return;
    body1.inverse_mass /= total;  // now the shares
    body2.inverse_mass /= total;
    body1.position += contact.normal * (depth * body1.inverse_mass);
    body2.position -= contact.normal * (depth * body2.inverse_mass);
    body1.inverse_mass *= total;
    body2.inverse_mass *= total;
}

}  // namespace workbook::projection
