// Mutant of chapter 1 for the grader's tests: a body is taken as immovable when its inverse mass is below a small epsilon, so a very heavy but movable body never moves
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    // "Comparing doubles with == is wrong", so: near zero counts as zero.
    if (w1 < 1e-6) return body1.velocity;
    if (w2 < 1e-6) return body2.velocity;
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

}  // namespace workbook::inelastic
