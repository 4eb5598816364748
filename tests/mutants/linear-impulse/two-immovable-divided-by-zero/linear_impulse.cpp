// Mutant of chapter 3 for the grader's tests: impulse_magnitude divides by w1 + w2 without a special case: NaN for two immovable bodies
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    const double approach = relative_normal_velocity(body1, body2, normal);
    return -(1.0 + restitution) * approach / (length_squared(normal) * (body1.inverse_mass + body2.inverse_mass));
}

}  // namespace workbook::linear_impulse
