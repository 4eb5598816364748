// Mutant of chapter 6 for the grader's tests: the increment is clamped into the cone instead of the accumulated sum
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    const double size = std::hypot(increment[0], increment[1]);
    double scale = 1.0;
    if (!(size <= static_coefficient * normal_impulse)) scale = dynamic_coefficient * normal_impulse / size;
    const std::array<double, 2> applied{increment[0] * scale, increment[1] * scale};
    accumulated[0] += applied[0];
    accumulated[1] += applied[1];
    return applied;
}

}  // namespace workbook::friction
