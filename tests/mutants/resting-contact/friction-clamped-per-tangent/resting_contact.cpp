// Mutant of chapter 5 for the grader's tests: each tangent's friction is clamped to +-mu Jn on its own (a square, not a disc)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
                      double friction) {
    const std::array<Vector3, 2> t = friction_tangents(contact.normal);
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        const Vector3& at = contact.points[i].position;
        const Vector3 slip = point_velocity(body1, at) - point_velocity(body2, at);
        const std::array<double, 2> before = p.friction;
        const double limit = friction * p.normal;
        for (std::size_t d = 0; d < 2; ++d)
            p.friction[d] = std::clamp(p.friction[d] - normal_mass(body1, body2, at, t[d]) * dot(slip, t[d]), -limit, limit);
        const Vector3 applied = (p.friction[0] - before[0]) * t[0] + (p.friction[1] - before[1]) * t[1];
        if (applied == Vector3{}) continue;
        apply_impulse(body1, body2, at, applied);
        largest = std::max(largest, length(applied) * (body1.inverse_mass + body2.inverse_mass));
    }
    return largest;
}

}  // namespace workbook::resting_contact
