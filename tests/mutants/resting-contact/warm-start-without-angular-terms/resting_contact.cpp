// Mutant of chapter 5 for the grader's tests: the warm start changes the velocities only, never the spins
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double j = impulses.points[i].normal;
        const Vector3& at = contact.points[i].position;
        body1.velocity += body1.inverse_mass * (j * contact.normal);
        body2.velocity -= body2.inverse_mass * (j * contact.normal);
        (void)at;
    }
}

}  // namespace workbook::resting_contact
