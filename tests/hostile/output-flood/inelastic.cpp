// Hostile submission for the grader's tests: energy_lost() writes 100 MB to stdout
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <vector>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    {
        const std::vector<char> line(1 << 20, 'x');
        for (int i = 0; i < 100; ++i) std::fwrite(line.data(), 1, line.size(), stdout);
        std::fflush(stdout);
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
