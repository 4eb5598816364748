// Mutant of chapter 1 for the grader's tests: the common velocity is the plain average of the two velocities, ignoring the masses
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    // Forgot the masses: the average of the velocities.
    return (body1.velocity + body2.velocity) / 2.0;
}

}  // namespace workbook::inelastic
