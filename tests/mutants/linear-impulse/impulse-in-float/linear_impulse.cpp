// Mutant of chapter 3 for the grader's tests: the impulse size is computed in float
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    const float inverse_mass_sum = static_cast<float>(body1.inverse_mass + body2.inverse_mass);
    if (inverse_mass_sum == 0.0f) return 0.0;
    const float approach = static_cast<float>(relative_normal_velocity(body1, body2, normal));
    return -(1.0f + static_cast<float>(restitution)) * approach / (static_cast<float>(length_squared(normal)) * inverse_mass_sum);
}

}  // namespace workbook::linear_impulse
