"""Benchmarks (speed.py: ./workbook bench speed); see CMakeLists.txt here."""
