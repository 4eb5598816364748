// Mutant of chapter 5 for the grader's tests: the warm start pushes body 1 along -n and body 2 along +n
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double j = impulses.points[i].normal;
        if (j != 0.0) apply_impulse(body2, body1, contact.points[i].position, j * contact.normal);
    }
}

}  // namespace workbook::resting_contact
