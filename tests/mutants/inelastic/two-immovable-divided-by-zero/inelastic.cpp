// Mutant of chapter 1 for the grader's tests: common_velocity divides by w1 + w2 without a special case, NaN for two immovable bodies
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0 && w2 != 0.0) return body1.velocity;
    if (w2 == 0.0 && w1 != 0.0) return body2.velocity;
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

}  // namespace workbook::inelastic
