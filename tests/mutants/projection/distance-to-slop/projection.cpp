// Mutant of chapter 2 for the grader's tests: depth_to_remove takes the distance to the slop, |depth - slop|, so a contact within the slop is pushed
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return knobs.fraction * std::abs(depth - knobs.slop);
}

}  // namespace workbook::projection
