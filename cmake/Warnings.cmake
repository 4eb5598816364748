# One place for the warning flags of the workbook's own targets; third-party headers come in
# as SYSTEM includes through their imported targets (or the SYSTEM property of a library built
# here, cmake/Dependencies.cmake), so they never trip -Werror. GCC and Clang (also Apple's)
# take the -W flags; MSVC gets its own, and only MSVC does. (WORKBOOK_WARNINGS_AS_ERRORS, in
# the top-level CMakeLists.txt, is OFF in the student presets: a student's build shows every
# warning and fails on none.)
include(CheckCXXCompilerFlag)
if(MSVC)
  # For every target, the libraries' too: /utf-8 reads the sources and writes the strings as
  # UTF-8 (the step report's "·"), /EHsc is standard C++ exceptions (CMake's default too).
  set(_workbook_warning_flags /W4 /permissive-)
  set(_workbook_error_flag /WX)
  add_compile_options(/utf-8 /EHsc)
else()
  set(_workbook_warning_flags -Wall -Wextra -Wpedantic -Wshadow -Wconversion)
  set(_workbook_error_flag -Werror)
  # Clang 22 calls __COUNTER__, which every Catch2 TEST_CASE expands to in our own files, a
  # C2y extension under -Wpedantic: one warning a test case, hundreds a build, none of them
  # about the workbook's code. (Older compilers do not know the flag: asked first.)
  check_cxx_compiler_flag(-Wc2y-extensions WORKBOOK_HAVE_WC2Y_EXTENSIONS)
  if(WORKBOOK_HAVE_WC2Y_EXTENSIONS)
    list(APPEND _workbook_warning_flags -Wno-c2y-extensions)
  endif()
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
