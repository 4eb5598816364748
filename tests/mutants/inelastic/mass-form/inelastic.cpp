// Correct variant of chapter 1 for the grader's tests: the common velocity written with masses, (m1 v1 + m2 v2) / (m1 + m2), immovable bodies first
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    if (body1.is_immovable()) return body1.velocity;
    if (body2.is_immovable()) return body2.velocity;
    const double m1 = body1.mass();
    const double m2 = body2.mass();
    return (m1 * body1.velocity + m2 * body2.velocity) / (m1 + m2);
}

}  // namespace workbook::inelastic
