// Mutant of chapter 6 for the grader's tests: the angular terms use the body-frame inertia's inverse instead of the world inverse inertia
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(inverse(body1.inertia_body) * cross(r1, tangent), r1) * (body1.inverse_mass > 0.0 ? 1.0 : 0.0);
    const Vector3 turn2 = cross(inverse(body2.inertia_body) * cross(r2, tangent), r2) * (body2.inverse_mass > 0.0 ? 1.0 : 0.0);
    const double k = body1.inverse_mass + body2.inverse_mass + dot(tangent, turn1 + turn2);
    return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace workbook::friction
