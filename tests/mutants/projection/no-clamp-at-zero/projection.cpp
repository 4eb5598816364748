// Mutant of chapter 2 for the grader's tests: depth minus slop is not clamped at zero, so a contact shallower than the slop pulls the bodies together
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return knobs.fraction * (depth - knobs.slop);
}

}  // namespace workbook::projection
