// Mutant of chapter 4 for the grader's tests: several points are solved together with no sign condition, so a receding point pulls
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::angular_impulse {

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3& n = contact.normal;
    const double e = combined_restitution(body1, body2);
    bool approaching = false;
    for (std::size_t i = 0; i < contact.point_count; ++i)
        approaching = approaching || dot(point_velocity(body1, contact.points[i].position) - point_velocity(body2, contact.points[i].position), n) < 0.0;
    if (!approaching) return;
    if (contact.point_count == 1) {
        const Vector3& p = contact.points[0].position;
        apply_impulse(body1, body2, p, impulse_magnitude(body1, body2, p, n, e) * n);
        return;
    }
    // Jacobi sweeps towards every point's target, impulses of any sign.
    const std::size_t count = contact.point_count;
    double target[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < count; ++i) {
        const Vector3 p = contact.points[i].position;
        const double u = dot(point_velocity(body1, p) - point_velocity(body2, p), n);
        target[i] = u < 0.0 ? -e * u : u;  // a receding point is held at its own speed
    }
    for (int sweep = 0; sweep < 2000; ++sweep)
        for (std::size_t i = 0; i < count; ++i) {
            const Vector3 p = contact.points[i].position;
            const double k = impulse_denominator(body1, body2, p, n);
            if (k == 0.0) return;
            const double u = dot(point_velocity(body1, p) - point_velocity(body2, p), n);
            apply_impulse(body1, body2, p, ((target[i] - u) / k) * n);
        }
}

}  // namespace workbook::angular_impulse
