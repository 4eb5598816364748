// Correct variant of chapter 3 for the grader's tests: the normal normalised first, |n| divided out once
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cmath>
namespace workbook::linear_impulse {

double relative_normal_velocity(const RigidBody& body1, const RigidBody& body2, const Vector3& normal) {
    return dot(body1.velocity, normal) - dot(body2.velocity, normal);
}

double impulse_magnitude(const RigidBody& body1, const RigidBody& body2, const Vector3& normal, double restitution) {
    const double w = body1.inverse_mass + body2.inverse_mass;
    if (w <= 0.0) return 0.0;
    const double size = std::sqrt(dot(normal, normal));
    const Vector3 unit = normal / size;
    const double j_unit = (1.0 + restitution) * -dot(body1.velocity - body2.velocity, unit) / w;
    return j_unit / size;
}

}  // namespace workbook::linear_impulse
