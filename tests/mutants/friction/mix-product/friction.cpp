// Mutant of chapter 6 for the grader's tests: the pair's coefficient is the product mu1 mu2, without the square root
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double mix_coefficients(double mu1, double mu2) {
    return mu1 * mu2;
}

}  // namespace workbook::friction
