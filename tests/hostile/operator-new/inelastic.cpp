// Hostile submission for the grader's tests: replaces the global operator new
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdlib>
#include <new>
void* operator new(std::size_t size) { return std::malloc(size ? size : 1); }
namespace workbook::inelastic {

}  // namespace workbook::inelastic
