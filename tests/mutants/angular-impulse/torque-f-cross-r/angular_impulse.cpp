// Mutant of chapter 4 for the grader's tests: the torque is written F x r instead of r x F
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += world_inverse_inertia(body1) * cross(impulse, point - body1.position);  // F x r
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity -= world_inverse_inertia(body2) * cross(impulse, point - body2.position);  // F x r
}

}  // namespace workbook::angular_impulse
