// Mutant of chapter 2 for the grader's tests: only the fraction is applied, the slop is never subtracted
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return knobs.fraction * depth;
}

}  // namespace workbook::projection
