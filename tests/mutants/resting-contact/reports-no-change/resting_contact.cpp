// Mutant of chapter 5 for the grader's tests: solve_velocity() returns 0, so the world stops after one pass
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    (void)pass(body1, body2, contact, impulses, &PointImpulse::bounce, &PointImpulse::normal);
    return 0.0;
}

}  // namespace workbook::resting_contact
