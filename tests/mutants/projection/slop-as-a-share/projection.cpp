// Mutant of chapter 2 for the grader's tests: the slop is taken as a share of the depth, fraction * depth * (1 - slop)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::projection {

double depth_to_remove(double depth, const PositionCorrection& knobs) {
    return knobs.fraction * std::max(depth * (1.0 - knobs.slop), 0.0);
}

}  // namespace workbook::projection
