// Mutant of chapter 1 for the grader's tests: energy_lost as the kinetic energy before minus after, each from 1/2 m v^2
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    const Vector3 shared = common_velocity(body1, body2);
    const double m1 = body1.mass();
    const double m2 = body2.mass();
    const double before = 0.5 * m1 * length_squared(body1.velocity) + 0.5 * m2 * length_squared(body2.velocity);
    const double after = 0.5 * (m1 + m2) * length_squared(shared);
    return before - after;
}

}  // namespace workbook::inelastic
