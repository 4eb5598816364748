// Mutant of chapter 4 for the grader's tests: the denominator's angular term is body 1's alone
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

double impulse_denominator(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    const Vector3 r1 = point - body1.position;
    const Vector3 turn1 = cross(world_inverse_inertia(body1) * cross(r1, normal), r1);
    return (body1.inverse_mass + body2.inverse_mass) * dot(normal, normal) + dot(normal, turn1);
}

}  // namespace workbook::angular_impulse
