// Correct variant of chapter 5 for the grader's tests: the warm start pushes body 2 first and writes the linear and angular parts out; right, and must keep full marks
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void warm_start(RigidBody& body1, RigidBody& body2, const Contact& contact, const ContactImpulses& impulses) {
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const double j = impulses.points[i].normal;
        const Vector3& at = contact.points[i].position;
        if (j == 0.0) continue;
        const Vector3 impulse = j * contact.normal;
        body2.angular_velocity -= body2.inverse_inertia_world * cross(at - body2.position, impulse);
        body2.velocity -= body2.inverse_mass * impulse;
        body1.angular_velocity += body1.inverse_inertia_world * cross(at - body1.position, impulse);
        body1.velocity += body1.inverse_mass * impulse;
    }
}

}  // namespace workbook::resting_contact
