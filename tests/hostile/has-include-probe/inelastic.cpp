// Hostile submission for the grader's tests: probes for the reference solution with __has_include (a comment before its parenthesis), to learn from the grader's answer whether the file is there
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#if __has_include/**/("/autograder/source/workbook/solutions/inelastic.cpp") || __has_include/**/("../../../solutions/inelastic.cpp")
#define FOUND_SOLUTION 1
#endif
namespace workbook::inelastic {

}  // namespace workbook::inelastic
