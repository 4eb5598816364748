// Hostile submission for the grader's tests: includes the reference solution by a path that leaves the submission
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#if __has_include("../../solutions/inelastic.cpp")
#include "../../solutions/inelastic.cpp"
#endif
namespace workbook::inelastic {

}  // namespace workbook::inelastic
