// Mutant of chapter 2 for the grader's tests: depths beyond the slop by less than a micrometre are treated as none
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return (depth - knobs.slop < 1e-6) ? 0.0 : knobs.fraction * (depth - knobs.slop);
}

}  // namespace workbook::projection
