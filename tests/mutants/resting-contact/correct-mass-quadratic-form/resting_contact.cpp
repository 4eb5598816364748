// Correct variant of chapter 5 for the grader's tests: normal_mass with the angular term as (r x n) . I^-1 (r x n), the same number in another form; right, and must keep full marks
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    const Vector3 a1 = cross(point - body1.position, normal);
    const Vector3 a2 = cross(point - body2.position, normal);
    const double k = body1.inverse_mass + body2.inverse_mass + dot(a1, body1.inverse_inertia_world * a1) +
                     dot(a2, body2.inverse_inertia_world * a2);
    return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace workbook::resting_contact
