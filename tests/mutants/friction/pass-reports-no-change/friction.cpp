// Mutant of chapter 6 for the grader's tests: the pass returns 0: the solver believes friction converged after one pass
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
        apply_impulse(body1, body2, at, impulse);
        const Vector3 change = point_velocity(body1, at) - point_velocity(body2, at) - slip;
        (void)change;
    }
    return largest;
}

}  // namespace workbook::friction
