# Reads chapters/CHAPTERS (one chapter id a line, '#' starts a comment) into
# WORKBOOK_CHAPTERS, by the same rule as tools/workbook_files.py and ./workbook.
file(STRINGS "${CMAKE_CURRENT_SOURCE_DIR}/chapters/CHAPTERS" _chapter_lines)
set(WORKBOOK_CHAPTERS "")
foreach(_line IN LISTS _chapter_lines)
  string(REGEX REPLACE "#.*" "" _line "${_line}")
  string(STRIP "${_line}" _line)
  if(_line)
    list(APPEND WORKBOOK_CHAPTERS "${_line}")
  endif()
endforeach()

# The random seed of every test run, check and grade (tests/RANDOM_SEED).
file(STRINGS "${CMAKE_CURRENT_SOURCE_DIR}/tests/RANDOM_SEED" WORKBOOK_TEST_SEED LIMIT_COUNT 1)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  "${CMAKE_CURRENT_SOURCE_DIR}/chapters/CHAPTERS" "${CMAKE_CURRENT_SOURCE_DIR}/tests/RANDOM_SEED")

# The reference solutions are absent from the student pack; everything that needs them is
# built only when they are there.
if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/solutions")
  set(WORKBOOK_HAVE_SOLUTIONS ON)
else()
  set(WORKBOOK_HAVE_SOLUTIONS OFF)
endif()
if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/tests/hidden")
  set(WORKBOOK_HAVE_HIDDEN_TESTS ON)
else()
  set(WORKBOOK_HAVE_HIDDEN_TESTS OFF)
endif()

# SKELETON_DIR lets the grader build a student's submission in place of skeleton/.
set(WORKBOOK_SKELETON_DIR "${CMAKE_CURRENT_SOURCE_DIR}/skeleton" CACHE PATH "Folder holding the student's responder sources")
