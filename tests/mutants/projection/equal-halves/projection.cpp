// Mutant of chapter 2 for the grader's tests: each movable body takes half the depth whatever the masses (all of it against an immovable one)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth <= 0.0) return;
    const double share1 = body1.is_immovable() ? 0.0 : body2.is_immovable() ? 1.0 : 0.5;
    body1.position += contact.normal * (depth * share1);
    body2.position -= contact.normal * (depth * (1.0 - share1));
}

}  // namespace workbook::projection
