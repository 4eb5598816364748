// Mutant of chapter 4 for the grader's tests: impulse_magnitude takes u from the centres' velocities, not the point's
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal,
                         double restitution) {
    const double k = impulse_denominator(body1, body2, point, normal);
    if (k == 0.0) return 0.0;
    const double u = dot(body1.velocity - body2.velocity, normal);
    return -(1.0 + restitution) * u / k;
}

}  // namespace workbook::angular_impulse
