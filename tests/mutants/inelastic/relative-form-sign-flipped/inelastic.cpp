// Mutant of chapter 1 for the grader's tests: the relative form of the common velocity with the difference the wrong way round, v1 + (v1 - v2) w1 / (w1 + w2)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0) return body1.velocity;
    return body1.velocity + (body1.velocity - body2.velocity) * (w1 / (w1 + w2));
}

}  // namespace workbook::inelastic
