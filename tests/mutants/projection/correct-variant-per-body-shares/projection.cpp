// Correct variant of chapter 2 for the grader's tests (must keep full marks): each share computed on its own, the deepest point found by a loop over the points
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double total = body1.inverse_mass + body2.inverse_mass;
    if (total <= 0.0) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    const double share1 = body1.inverse_mass / total;
    const double share2 = body2.inverse_mass / total;
    body1.position = body1.position + contact.normal * (depth * share1);
    body2.position = body2.position - contact.normal * (depth * share2);
}

}  // namespace workbook::projection
