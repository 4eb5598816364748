// Mutant of chapter 4 for the grader's tests: both lever arms are measured from body 1's centre
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    const Vector3 r = point - body1.position;  // one lever arm for both bodies
    const Vector3 turn1 = cross(world_inverse_inertia(body1) * cross(r, normal), r);
    const Vector3 turn2 = cross(world_inverse_inertia(body2) * cross(r, normal), r);
    return (body1.inverse_mass + body2.inverse_mass) * dot(normal, normal) + dot(normal, turn1 + turn2);
}

void apply_impulse(RigidBody& body1, RigidBody& body2, const Vector3& point, const Vector3& impulse) {
    const Vector3 r = point - body1.position;  // one lever arm for both bodies
    body1.velocity += body1.inverse_mass * impulse;
    body1.angular_velocity += world_inverse_inertia(body1) * cross(r, impulse);
    body2.velocity -= body2.inverse_mass * impulse;
    body2.angular_velocity -= world_inverse_inertia(body2) * cross(r, impulse);
}

}  // namespace workbook::angular_impulse
