// Mutant of chapter 6 for the grader's tests: only body 1's angular term is in the tangential mass
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double tangent_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& tangent) {
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(body1.inverse_inertia_world * cross(r1, tangent), r1);
    const Vector3 turn2 = cross(body2.inverse_inertia_world * cross(r2, tangent), r2);
    const double k = body1.inverse_mass + body2.inverse_mass + dot(tangent, turn1);
    return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace workbook::friction
