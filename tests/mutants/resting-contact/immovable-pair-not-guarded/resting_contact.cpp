// Mutant of chapter 5 for the grader's tests: normal_mass divides by k without the guard for two immovable bodies
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    const Vector3 r1 = point - body1.position;
    const Vector3 r2 = point - body2.position;
    const Vector3 turn1 = cross(body1.inverse_inertia_world * cross(r1, normal), r1);
    const Vector3 turn2 = cross(body2.inverse_inertia_world * cross(r2, normal), r2);
    return 1.0 / (body1.inverse_mass + body2.inverse_mass + dot(normal, turn1 + turn2));
}

}  // namespace workbook::resting_contact
