// Mutant of chapter 5 for the grader's tests: the effective mass leaves out the angular terms (chapter 3's 1/(1/m1 + 1/m2))
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double normal_mass(const RigidBody& body1, const RigidBody& body2, const Vector3& point, const Vector3& normal) {
    (void)point;
    (void)normal;
    const double k = body1.inverse_mass + body2.inverse_mass;
    return k > 0.0 ? 1.0 / k : 0.0;
}

}  // namespace workbook::resting_contact
