// Mutant of chapter 1 for the grader's tests: energy_lost forgets the 1/2
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return length_squared(body1.velocity - body2.velocity) / inverse_mass_sum;
}

}  // namespace workbook::inelastic
