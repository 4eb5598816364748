// Mutant of chapter 2 for the grader's tests: each movable body is pushed the whole depth, so the pair ends up twice as far apart as needed and the centre of mass moves
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const Vector3 push = contact.normal * depth_to_remove(contact.penetration, knobs);
    if (!body1.is_immovable()) body1.position += push;
    if (!body2.is_immovable()) body2.position -= push;
}

}  // namespace workbook::projection
