// Mutant of chapter 5 for the grader's tests: accumulate ignores a negative increment: what was given stays
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::resting_contact {

double accumulate(double& accumulated, double increment) {
    if (increment <= 0.0) return 0.0;
    accumulated += increment;
    return increment;
}

}  // namespace workbook::resting_contact
