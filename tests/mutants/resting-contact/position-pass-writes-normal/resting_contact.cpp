// Mutant of chapter 5 for the grader's tests: the position pass sums its impulse into normal instead of pseudo
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return pass(body1, body2, contact, impulses, &PointImpulse::bias, &PointImpulse::normal);
}

}  // namespace workbook::resting_contact
