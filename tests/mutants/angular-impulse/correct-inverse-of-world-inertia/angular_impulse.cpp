// Correct variant of chapter 4 for the grader's tests: the world inverse inertia as the inverse of R I R^T, the same matrix
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    return inverse(body.inertia_world());
}

}  // namespace workbook::angular_impulse
