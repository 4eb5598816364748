// Correct variant of chapter 1 for the grader's tests: the common velocity written as body 1's velocity plus a share of the relative velocity, v1 + (v2 - v1) w1 / (w1 + w2); right, and must keep full marks
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return body1.velocity;
    // Body 1 moves towards body 2's velocity by the share of the mass body 2 holds.
    return body1.velocity + (body2.velocity - body1.velocity) * (w1 / (w1 + w2));
}

}  // namespace workbook::inelastic
