// Mutant of chapter 1 for the grader's tests: an immovable body is taken to be at rest: common_velocity returns zero against it
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0 || w2 == 0.0) return Vector3{};
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

}  // namespace workbook::inelastic
