// Mutant of chapter 6 for the grader's tests: the pair's coefficient is the larger of the two
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double mix_coefficients(double mu1, double mu2) {
    return std::max(mu1, mu2);
}

}  // namespace workbook::friction
