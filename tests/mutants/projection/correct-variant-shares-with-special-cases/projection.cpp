// Correct variant of chapter 2 for the grader's tests (must keep full marks): masses with explicit immovable cases, and the depth clamp written as an early return
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    if (depth <= knobs.slop) return 0.0;
    return (depth - knobs.slop) * knobs.fraction;
}

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth == 0.0 || (body1.is_immovable() && body2.is_immovable())) return;
    if (body1.is_immovable()) {
        body2.position -= depth * contact.normal;
        return;
    }
    if (body2.is_immovable()) {
        body1.position += depth * contact.normal;
        return;
    }
    const double m1 = body1.mass();
    const double m2 = body2.mass();
    body1.position += (depth * m2 / (m1 + m2)) * contact.normal;
    body2.position -= (depth * m1 / (m1 + m2)) * contact.normal;
}

}  // namespace workbook::projection
