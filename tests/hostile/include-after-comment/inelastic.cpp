// Hostile submission for the grader's tests: hides an #include of /etc/passwd from a textual screen with a comment between '#' and 'include', so that the compiler would quote it in its errors
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#/**/include "/etc/passwd"
namespace workbook::inelastic {

}  // namespace workbook::inelastic
