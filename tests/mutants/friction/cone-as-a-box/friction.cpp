// Mutant of chapter 6 for the grader's tests: each tangent's friction is clamped on its own to [-mu J_n, mu J_n]: a square instead of the disc
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    const std::array<double, 2> before = accumulated;
    for (std::size_t d = 0; d < 2; ++d) {
        const double sum = accumulated[d] + increment[d];
        accumulated[d] = std::abs(sum) <= static_coefficient * normal_impulse
                             ? sum
                             : std::clamp(sum, -dynamic_coefficient * normal_impulse, dynamic_coefficient * normal_impulse);
    }
    return {accumulated[0] - before[0], accumulated[1] - before[1]};
}

}  // namespace workbook::friction
