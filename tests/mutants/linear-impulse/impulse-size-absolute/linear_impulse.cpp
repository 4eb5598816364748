// Mutant of chapter 3 for the grader's tests: impulse_magnitude returns |J|, as if it could never be negative
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    const double approach = relative_normal_velocity(body1, body2, normal);
    return std::abs((1.0 + restitution) * approach / (length_squared(normal) * inverse_mass_sum));
}

}  // namespace workbook::linear_impulse
