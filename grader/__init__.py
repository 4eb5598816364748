"""The instructor's grader (./workbook grade, ./workbook pack); see README.md here.
Run its programs from the workbook's folder: python3 -m grader.grade --help."""
