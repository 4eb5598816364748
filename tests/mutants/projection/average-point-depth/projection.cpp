// Mutant of chapter 2 for the grader's tests: the depth is the average of the points' depths instead of contact.penetration
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

void correct(RigidBody& body1, RigidBody& body2, const Contact& contact, const PositionCorrection& knobs) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 + w2 == 0.0 || contact.point_count == 0) return;
    double sum = 0.0;
    for (std::size_t i = 0; i < contact.point_count; ++i) sum += contact.points[i].penetration;
    const double depth = depth_to_remove(sum / contact.point_count, knobs);
    if (depth <= 0.0) return;
    body1.position += contact.normal * (depth * w1 / (w1 + w2));
    body2.position -= contact.normal * (depth * w2 / (w1 + w2));
}

}  // namespace workbook::projection
