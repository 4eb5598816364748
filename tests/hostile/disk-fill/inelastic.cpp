// Hostile submission for the grader's tests: energy_lost() fills the disk with 8 MiB files (each below the file-size limit), up to 1.5 GiB
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <string>
#include <vector>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    {
        const std::vector<char> block(8 << 20, 'x');
        for (int i = 0; i < 192; ++i) {
            std::FILE* file = std::fopen(("fill-" + std::to_string(i)).c_str(), "wb");
            if (file == nullptr) break;
            std::fwrite(block.data(), 1, block.size(), file);
            std::fclose(file);
        }
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
