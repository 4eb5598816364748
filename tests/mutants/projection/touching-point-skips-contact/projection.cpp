// Mutant of chapter 2 for the grader's tests: correct leaves the contact alone when any of its points is exactly 0 deep (only touching)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    for (std::size_t i = 0; i < contact.point_count; ++i)
        if (contact.points[i].penetration == 0.0) return;  // "touching, not overlapping"
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0) return;
    const double depth = depth_to_remove(contact.penetration, knobs);
    if (depth <= 0.0) return;
    body1.position += contact.normal * (depth * w1 / (w1 + w2));
    body2.position -= contact.normal * (depth * w2 / (w1 + w2));
}

}  // namespace workbook::projection
