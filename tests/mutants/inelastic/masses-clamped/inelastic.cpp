// Mutant of chapter 1 for the grader's tests: masses clamped to 1e-6 to 1e6 kg (and a wall to a million kilograms) to keep the numbers tame
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double m1 = body1.is_immovable() ? 1e6 : std::min(std::max(body1.mass(), 1e-6), 1e6);
    const double m2 = body2.is_immovable() ? 1e6 : std::min(std::max(body2.mass(), 1e-6), 1e6);
    return (m1 * body1.velocity + m2 * body2.velocity) / (m1 + m2);
}

}  // namespace workbook::inelastic
