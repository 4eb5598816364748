# Reads chapters/CHAPTERS (one chapter id a line, '#' comments) into WORKBOOK_CHAPTERS.
file(STRINGS "${CMAKE_CURRENT_SOURCE_DIR}/chapters/CHAPTERS" _chapter_lines)
set(WORKBOOK_CHAPTERS "")
foreach(_line IN LISTS _chapter_lines)
  string(STRIP "${_line}" _line)
  if(_line AND NOT _line MATCHES "^#")
    list(APPEND WORKBOOK_CHAPTERS "${_line}")
  endif()
endforeach()

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
