// Mutant of chapter 5 for the grader's tests: the warm start turns body 2 about body 1's lever arm
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double j = impulses.points[i].normal;
        const Vector3& at = contact.points[i].position;
        const Vector3 impulse = j * contact.normal;
        const Vector3 r1 = at - body1.position;
        body1.velocity += body1.inverse_mass * impulse;
        body1.angular_velocity += body1.inverse_inertia_world * cross(r1, impulse);
        body2.velocity -= body2.inverse_mass * impulse;
        body2.angular_velocity -= body2.inverse_inertia_world * cross(r1, impulse);
    }
}

}  // namespace workbook::resting_contact
