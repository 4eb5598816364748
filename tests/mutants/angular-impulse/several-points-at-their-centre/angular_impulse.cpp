// Mutant of chapter 4 for the grader's tests: several points are resolved as one impulse at their centre
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
    Vector3 centre{};
    for (std::size_t i = 0; i < contact.point_count; ++i) centre += contact.points[i].position;
    centre = centre / static_cast<double>(contact.point_count);
    const double j = impulse_magnitude(body1, body2, centre, n, e);
    if (j > 0.0) apply_impulse(body1, body2, centre, j * n);
}

}  // namespace workbook::angular_impulse
