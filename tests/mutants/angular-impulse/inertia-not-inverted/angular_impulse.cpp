// Mutant of chapter 4 for the grader's tests: the inertia I is used where its inverse I^-1 belongs
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    const Matrix3 r = to_matrix(body.orientation);
    return r * body.inertia_body * transpose(r);  // I, not I^-1
}

}  // namespace workbook::angular_impulse
