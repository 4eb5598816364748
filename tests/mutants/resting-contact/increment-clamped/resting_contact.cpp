// Mutant of chapter 5 for the grader's tests: each pass's impulse is clamped at zero instead of the accumulated sum
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double accumulate(double& accumulated, double increment) {
    const double applied = std::max(increment, 0.0);
    accumulated += applied;
    return applied;
}

}  // namespace workbook::resting_contact
