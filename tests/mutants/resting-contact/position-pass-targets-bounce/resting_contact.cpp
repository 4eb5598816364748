// Mutant of chapter 5 for the grader's tests: the position pass aims for the bounce target instead of the bias
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double solve_position(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    return pass(body1, body2, contact, impulses, &PointImpulse::bounce, &PointImpulse::pseudo);
}

}  // namespace workbook::resting_contact
