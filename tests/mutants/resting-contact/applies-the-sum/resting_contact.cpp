// Mutant of chapter 5 for the grader's tests: the velocity pass applies the whole accumulated impulse again, not its change
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double solve_velocity(RigidBody& body1, RigidBody& body2, const Contact& contact, ContactImpulses& impulses) {
    double largest = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        if (p.mass == 0.0) continue;
        const Vector3& at = contact.points[i].position;
        const double u = normal_velocity(body1, body2, at, contact.normal);
        const double applied = accumulate(p.normal, p.mass * (p.bounce - u));
        if (applied == 0.0) continue;
        apply_impulse(body1, body2, at, p.normal * contact.normal);
        largest = std::max(largest, std::abs(applied) / p.mass);
    }
    return largest;
}

}  // namespace workbook::resting_contact
