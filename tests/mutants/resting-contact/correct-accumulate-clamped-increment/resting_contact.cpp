// Correct variant of chapter 5 for the grader's tests: accumulate as the increment clamped at minus the sum so far, max(dJ, -J): the same clamp of the sum; right, and must keep full marks
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double accumulate(double& accumulated, double increment) {
    const double applied = std::max(increment, -accumulated);
    accumulated = std::max(accumulated + applied, 0.0);
    return applied;
}

}  // namespace workbook::resting_contact
