// Mutant of chapter 1 for the grader's tests: energy_lost squares the difference of the speeds, (|v1| - |v2|)^2, not the length of v1 - v2
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    const double d = length(body1.velocity) - length(body2.velocity);
    return 0.5 / inverse_mass_sum * d * d;
}

}  // namespace workbook::inelastic
