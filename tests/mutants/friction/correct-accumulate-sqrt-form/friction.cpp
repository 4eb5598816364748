// Correct variant of chapter 6 for the grader's tests: the length written sqrt(x^2 + y^2), the slide scaling each component by mu_d J_n / |sum| in a branch of its own
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    const double x = accumulated[0] + increment[0];
    const double y = accumulated[1] + increment[1];
    const double size = std::sqrt(x * x + y * y);
    const double limit = static_coefficient * normal_impulse;
    std::array<double, 2> after{x, y};
    if (size > limit) after = {x * (dynamic_coefficient * normal_impulse) / size, y * (dynamic_coefficient * normal_impulse) / size};
    const std::array<double, 2> change{after[0] - accumulated[0], after[1] - accumulated[1]};
    accumulated = after;
    return change;
}

}  // namespace workbook::friction
