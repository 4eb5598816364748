// Mutant of chapter 5 for the grader's tests: accumulate returns the new sum instead of its change
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double accumulate(double& accumulated, double increment) {
    accumulated = std::max(accumulated + increment, 0.0);
    return accumulated;
}

}  // namespace workbook::resting_contact
