# One place for the warning flags of the workbook's own targets; third-party headers come
# in as SYSTEM includes through their imported targets, so they never trip -Werror.
add_library(workbook_warnings INTERFACE)
target_compile_options(workbook_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast
  -Wnon-virtual-dtor -Woverloaded-virtual -Wdouble-promotion
  $<$<BOOL:${WORKBOOK_WARNINGS_AS_ERRORS}>:-Werror>)

# The student's own code gets the same warnings, but as errors only when asked: a student
# with an unused variable should still see which physics steps pass.
option(WORKBOOK_STUDENT_WARNINGS_AS_ERRORS "Treat warnings in skeleton/ as errors (on for the workbook's own CI)" OFF)
add_library(workbook_student_warnings INTERFACE)
target_compile_options(workbook_student_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  $<$<BOOL:${WORKBOOK_STUDENT_WARNINGS_AS_ERRORS}>:-Werror>)
