// Mutant of chapter 6 for the grader's tests: body 2 gets +J as body 1 does
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    const double static_coefficient = mix_coefficients(body1.static_friction, body2.static_friction);
    const double dynamic_coefficient = mix_coefficients(body1.friction, body2.friction);
    const std::array<Vector3, 2> t = tangent_basis(contact.normal);
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        const Vector3& at = contact.points[i].position;
        const Vector3 slip = point_velocity(body1, at) - point_velocity(body2, at);
        std::array<double, 2> increment{};
        for (std::size_t d = 0; d < 2; ++d) increment[d] = -tangent_mass(body1, body2, at, t[d]) * dot(slip, t[d]);
        const std::array<double, 2> applied = accumulate_friction(p.friction, increment, p.normal, static_coefficient, dynamic_coefficient);
        const Vector3 impulse = applied[0] * t[0] + applied[1] * t[1];
        if (impulse == Vector3{}) continue;
        body1.velocity += body1.inverse_mass * impulse;
        body1.angular_velocity += body1.inverse_inertia_world * cross(at - body1.position, impulse);
        body2.velocity += body2.inverse_mass * impulse;
        body2.angular_velocity += body2.inverse_inertia_world * cross(at - body2.position, impulse);
        const Vector3 change = point_velocity(body1, at) - point_velocity(body2, at) - slip;
        largest = std::max(largest, length(change - dot(change, contact.normal) * contact.normal));
    }
    return largest;
}

}  // namespace workbook::friction
