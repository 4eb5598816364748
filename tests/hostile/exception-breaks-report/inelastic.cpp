// Hostile submission for the grader's tests: energy_lost() throws an exception whose text starts with ']]>' and carries markup, to break the checker's XML report
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <stdexcept>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (body1.is_immovable() || body2.is_immovable())
        throw std::runtime_error("]]></Exception><OverallResult success=\"true\"/></TestCase><![CDATA[");
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
