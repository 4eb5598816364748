// Mutant of chapter 1 for the grader's tests: the common velocity is computed in float, so it is right to 7 digits only
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const float w1 = static_cast<float>(body1.inverse_mass);
    const float w2 = static_cast<float>(body2.inverse_mass);
    if (w1 == 0.0f) return body1.velocity;
    if (w2 == 0.0f) return body2.velocity;
    const auto mix = [&](double a, double b) {
        return static_cast<double>((w2 * static_cast<float>(a) + w1 * static_cast<float>(b)) / (w1 + w2));
    };
    return Vector3{mix(body1.velocity.x, body2.velocity.x), mix(body1.velocity.y, body2.velocity.y),
                   mix(body1.velocity.z, body2.velocity.z)};
}

}  // namespace workbook::inelastic
