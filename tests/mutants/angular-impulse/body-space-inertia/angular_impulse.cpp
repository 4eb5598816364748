// Mutant of chapter 4 for the grader's tests: the body-frame inverse inertia is used in world formulas (no rotation)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Matrix3 world_inverse_inertia(const RigidBody& body) {
    if (body.is_immovable()) return Matrix3::zero();
    return inverse(body.inertia_body);  // forgot R ... R^T
}

}  // namespace workbook::angular_impulse
