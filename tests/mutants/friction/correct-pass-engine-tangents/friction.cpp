// Correct variant of chapter 6 for the grader's tests: the pass reads its tangents from the engine's friction_tangents() and writes the point velocities out
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double solve_friction(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    const double mu_s = mix_coefficients(body1.static_friction, body2.static_friction);
    const double mu_d = mix_coefficients(body1.friction, body2.friction);
    const std::array<Vector3, 2> t = friction_tangents(contact.normal);
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        const Vector3 at = contact.points[i].position;
        const Vector3 r1 = at - body1.position;
        const Vector3 r2 = at - body2.position;
        const Vector3 before = (body1.velocity + cross(body1.angular_velocity, r1)) - (body2.velocity + cross(body2.angular_velocity, r2));
        const std::array<double, 2> increment{-tangent_mass(body1, body2, at, t[0]) * dot(before, t[0]),
                                              -tangent_mass(body1, body2, at, t[1]) * dot(before, t[1])};
        const std::array<double, 2> applied = accumulate_friction(impulses.points[i].friction, increment, impulses.points[i].normal, mu_s, mu_d);
        const Vector3 j = applied[0] * t[0] + applied[1] * t[1];
        body1.velocity += body1.inverse_mass * j;
        body1.angular_velocity += body1.inverse_inertia_world * cross(r1, j);
        body2.velocity -= body2.inverse_mass * j;
        body2.angular_velocity -= body2.inverse_inertia_world * cross(r2, j);
        const Vector3 after = (body1.velocity + cross(body1.angular_velocity, r1)) - (body2.velocity + cross(body2.angular_velocity, r2));
        const Vector3 change = after - before;
        largest = std::max(largest, length(change - dot(change, contact.normal) * contact.normal));
    }
    return largest;
}

}  // namespace workbook::friction
