// Hostile submission for the grader's tests: common_velocity() calls std::abort() for two immovable bodies
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdlib>
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    if (body1.is_immovable() && body2.is_immovable()) std::abort();
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0) return body1.velocity;
    if (w2 == 0.0) return body2.velocity;
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

}  // namespace workbook::inelastic
