// Mutant of chapter 2 for the grader's tests: depth_to_remove caps the fraction at 1, so a fraction above 1 removes only the depth
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return std::min(knobs.fraction, 1.0) * std::max(depth - knobs.slop, 0.0);
}

}  // namespace workbook::projection
