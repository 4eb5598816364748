// Mutant of chapter 4 for the grader's tests: apply_impulse turns body 2 the same way as body 1 (+= instead of -=)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += world_inverse_inertia(body1) * cross(point - body1.position, impulse);
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity += world_inverse_inertia(body2) * cross(point - body2.position, impulse);
}

}  // namespace workbook::angular_impulse
