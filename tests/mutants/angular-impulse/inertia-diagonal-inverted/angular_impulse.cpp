// Mutant of chapter 4 for the grader's tests: the inverse inertia inverts each diagonal entry of inertia_body (1/Ixx, 1/Iyy, 1/Izz) and drops the rest
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    const Matrix3& i = body.inertia_body;
    const Matrix3 r = to_matrix(body.orientation);
    return r * Matrix3::diagonal({1.0 / i(0, 0), 1.0 / i(1, 1), 1.0 / i(2, 2)}) * transpose(r);
}

}  // namespace workbook::angular_impulse
