// Mutant of chapter 5 for the grader's tests: prepare leaves the last step's pseudo-impulse in place
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

void prepare(const RigidBody& body1, const RigidBody& body2, const Contact& contact, ContactImpulses& impulses,
             const ContactSolverSettings& settings, const PositionCorrection& knobs, double dt) {
    const double e = combined_restitution(body1, body2);
    for (std::size_t i = 0; i < contact.point_count; ++i) {
        PointImpulse& p = impulses.points[i];
        const ContactPoint& point = contact.points[i];
        p.mass = normal_mass(body1, body2, point.position, contact.normal);
        const double u = normal_velocity(body1, body2, point.position, contact.normal);
        p.bounce = u < -settings.bounce_threshold ? -e * u : 0.0;
        p.bias = std::min(knobs.fraction * std::max(point.penetration - knobs.slop, 0.0), settings.max_push) / dt;
    }
}

}  // namespace workbook::resting_contact
