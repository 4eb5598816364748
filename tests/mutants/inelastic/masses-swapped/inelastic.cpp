// Mutant of chapter 1 for the grader's tests: each velocity is weighted by its own inverse mass, so the lighter body dominates
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return body1.velocity;
    return (w1 * body1.velocity + w2 * body2.velocity) / (w1 + w2);  // weights swapped
}

}  // namespace workbook::inelastic
