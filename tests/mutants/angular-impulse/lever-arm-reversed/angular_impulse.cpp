// Mutant of chapter 4 for the grader's tests: point_velocity uses the lever arm from the point to the centre, position - point
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

Vector3 point_velocity(const RigidBody& body, const Vector3& point) {
    return body.velocity + cross(body.angular_velocity, body.position - point);
}

}  // namespace workbook::angular_impulse
