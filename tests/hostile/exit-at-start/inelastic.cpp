// Hostile submission for the grader's tests: calls exit(0) while the program starts, before any test runs
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdlib>
namespace workbook::inelastic {

namespace {
// Runs during static initialisation, before Catch2 has written anything.
const int quit_now = (std::exit(0), 0);
}  // namespace

}  // namespace workbook::inelastic
