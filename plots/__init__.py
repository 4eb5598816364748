"""The figures, strobe pictures, animations and player data of the workbook (see README.md here).
Run from the workbook's folder as python3 -m plots.figures ...; CMake does."""
