// Mutant of chapter 2 for the grader's tests: the fraction is applied before the slop, max(fraction * depth - slop, 0)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return std::max(knobs.fraction * depth - knobs.slop, 0.0);
}

}  // namespace workbook::projection
