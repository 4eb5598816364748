"""The workbook's Python tools: ./workbook's front end (tools/cli), ./workbook check's runner
(check.py), the shared readers of Catch2's reports and of the workbook's plain-text facts, and
the one wording of crashes, time limits and NaN (wording.py).

The workbook's Python code is one tree of packages rooted at the workbook's folder (tools,
grader, docs, tests): a module imports another by its full name (`from tools import
catch_xml`), and a program runs from the workbook's folder as `python3 -m tools.check ...`.
./workbook, workbook.py, CMake and ctest start them that way."""
