// Mutant of chapter 1 for the grader's tests: resolve() merges only the velocity component along the normal
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    const Vector3 n = contact.normal;
    const double v1n = dot(body1.velocity, n);
    const double v2n = dot(body2.velocity, n);
    if (v1n - v2n >= 0.0) return;
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    const double shared = (w2 * v1n + w1 * v2n) / (w1 + w2);
    body1.velocity += (shared - v1n) * n;  // the tangential part is left as it was
    body2.velocity += (shared - v2n) * n;
}

}  // namespace workbook::inelastic
