// Mutant of chapter 3 for the grader's tests: the whole relative velocity is reversed instead of its normal part
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::linear_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    if (relative_normal_velocity(body1, body2, n) >= 0.0) return;
    const double e = combined_restitution(body1, body2);
    const double w = body1.inverse_mass + body2.inverse_mass;
    // An impulse vector along v12 rather than along n: v12' = -e v12, sliding included.
    const Vector3 impulse = -(1.0 + e) * (body1.velocity - body2.velocity) / w;
    body1.velocity += body1.inverse_mass * impulse;
    body2.velocity -= body2.inverse_mass * impulse;
}

}  // namespace workbook::linear_impulse
