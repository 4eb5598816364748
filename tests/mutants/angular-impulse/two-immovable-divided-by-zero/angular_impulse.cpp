// Mutant of chapter 4 for the grader's tests: impulse_magnitude divides by k without a special case: NaN for two immovable bodies
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution) {
    const double k = impulse_denominator(body1, body2, point, normal);
    const double u = dot(point_velocity(body1, point) - point_velocity(body2, point), normal);
    return -(1.0 + restitution) * u / k;
}

}  // namespace workbook::angular_impulse
