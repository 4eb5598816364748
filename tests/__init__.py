"""The workbook's tests (see CMakeLists.txt here). ctest runs the Python ones from the
workbook's folder as `python3 -m tests.<folder>.<file>`, so that they import the workbook's
modules by their full names (tools.check, grader.kit)."""
