// Mutant of chapter 3 for the grader's tests: e is applied to each body's absolute velocity instead of the relative one
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double e = combined_restitution(body1, body2);
    // Each body bounces off the normal on its own, as a ball off the floor would.
    if (!body1.is_immovable()) body1.velocity -= (1.0 + e) * dot(body1.velocity, n) * n;
    if (!body2.is_immovable()) body2.velocity -= (1.0 + e) * dot(body2.velocity, n) * n;
}

}  // namespace workbook::linear_impulse
