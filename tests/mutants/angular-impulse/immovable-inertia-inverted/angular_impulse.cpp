// Mutant of chapter 4 for the grader's tests: world_inverse_inertia inverts inertia_body without asking whether the body is immovable
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.inertia_body.m == Matrix3::zero().m) return Matrix3::zero();
    const Matrix3 r = to_matrix(body.orientation);
    return r * inverse(body.inertia_body) * transpose(r);
}

}  // namespace workbook::angular_impulse
