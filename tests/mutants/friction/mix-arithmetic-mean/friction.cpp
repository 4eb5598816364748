// Mutant of chapter 6 for the grader's tests: the pair's coefficient is the arithmetic mean (mu1 + mu2) / 2
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double mix_coefficients(double mu1, double mu2) {
    return (mu1 + mu2) / 2.0;
}

}  // namespace workbook::friction
