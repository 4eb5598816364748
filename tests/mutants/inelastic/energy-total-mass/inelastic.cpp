// Mutant of chapter 1 for the grader's tests: energy_lost uses the total mass m1 + m2 instead of the reduced mass
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (body1.is_immovable() || body2.is_immovable()) return 0.0;
    return 0.5 * (body1.mass() + body2.mass()) * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
