// Mutant of chapter 5 for the grader's tests: the warm start applies nothing
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    (void)body1;
    (void)body2;
    (void)contact;
    (void)impulses;
}

}  // namespace workbook::resting_contact
