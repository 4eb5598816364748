# One place for the warning flags of the workbook's own targets; third-party headers come
# in as SYSTEM includes through their imported targets, so they never trip -Werror.
# GCC and Clang (also Apple's) take the -W flags; MSVC gets its own, and only MSVC does.
if(MSVC)
  set(_workbook_warning_flags /W4 /permissive- /utf-8)
  set(_workbook_error_flag /WX)
else()
  set(_workbook_warning_flags -Wall -Wextra -Wpedantic -Wshadow -Wconversion)
  set(_workbook_error_flag -Werror)
endif()

add_library(workbook_warnings INTERFACE)
target_compile_options(workbook_warnings INTERFACE ${_workbook_warning_flags})
if(NOT MSVC)
  target_compile_options(workbook_warnings INTERFACE
    -Wsign-conversion -Wold-style-cast -Wnon-virtual-dtor -Woverloaded-virtual -Wdouble-promotion)
endif()
if(WORKBOOK_WARNINGS_AS_ERRORS)
  target_compile_options(workbook_warnings INTERFACE ${_workbook_error_flag})
endif()

# The student's own code gets the same warnings, shown and never fatal, in every command
# (check, run, figures, book, test): a student with an unused variable should still see
# which physics steps pass. The shipped skeleton is held warning-free by a test of its own
# (skeleton.warning_free in tests/CMakeLists.txt), not by failing a student's build.
add_library(workbook_student_warnings INTERFACE)
target_compile_options(workbook_student_warnings INTERFACE ${_workbook_warning_flags})
