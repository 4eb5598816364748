// Correct variant of chapter 6 for the grader's tests: the geometric mean written as sqrt(mu1) sqrt(mu2)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
namespace workbook::friction {

double mix_coefficients(double mu1, double mu2) {
    return std::sqrt(mu1) * std::sqrt(mu2);
}

}  // namespace workbook::friction
