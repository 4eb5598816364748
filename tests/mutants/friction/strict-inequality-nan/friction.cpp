// Mutant of chapter 6 for the grader's tests: sticking is tested with < instead of <=, so a zero sum with no normal impulse is scaled by 0/0 (NaN)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

std::array<double, 2> accumulate_friction(std::array<double, 2>& accumulated, const std::array<double, 2>& increment,
                                          double normal_impulse, double static_coefficient,
                                          double dynamic_coefficient) {
    const std::array<double, 2> before = accumulated;
    accumulated[0] += increment[0];
    accumulated[1] += increment[1];
    const double size = std::hypot(accumulated[0], accumulated[1]);
    if (!(size < static_coefficient * normal_impulse)) {
        const double scale = dynamic_coefficient * normal_impulse / size;
        accumulated[0] *= scale;
        accumulated[1] *= scale;
    }
    return {accumulated[0] - before[0], accumulated[1] - before[1]};
}

}  // namespace workbook::friction
