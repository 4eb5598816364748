// Mutant of chapter 4 for the grader's tests: the inverse inertia scales first and is rotated once, I^-1 R, instead of R I^-1 R^T
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    return inverse(body.inertia_body) * to_matrix(body.orientation);  // scale, then one rotation
}

}  // namespace workbook::angular_impulse
