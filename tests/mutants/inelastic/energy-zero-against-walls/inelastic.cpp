// Mutant of chapter 1 for the grader's tests: energy_lost returns 0 whenever a body is immovable
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (body1.is_immovable() || body2.is_immovable()) return 0.0;
    const double reduced_mass = 1.0 / (body1.inverse_mass + body2.inverse_mass);
    return 0.5 * reduced_mass * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
