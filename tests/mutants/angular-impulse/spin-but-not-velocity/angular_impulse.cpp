// Mutant of chapter 4 for the grader's tests: the impulse turns the bodies (w) but does not change their velocities (v)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    body1.angular_velocity += world_inverse_inertia(body1) * cross(point - body1.position, impulse);
    body2.angular_velocity -= world_inverse_inertia(body2) * cross(point - body2.position, impulse);
}

}  // namespace workbook::angular_impulse
