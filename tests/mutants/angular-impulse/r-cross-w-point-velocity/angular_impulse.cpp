// Mutant of chapter 4 for the grader's tests: the contact point's velocity adds r x w instead of w x r
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    return body.velocity + cross(point - body.position, body.angular_velocity);  // r x w
}

}  // namespace workbook::angular_impulse
