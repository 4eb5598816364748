#pragma once
/// \file
/// Reading back the time-series CSV the engine writes, for tests that check a figure's data.

#include <string>
#include <string_view>
#include <vector>

namespace workbook::testing {

/// A CSV read back: the header's column names and every row as numbers.
struct CsvTable {
    std::vector<std::string> names;
    std::vector<std::vector<double>> rows;

    /// Every value of the column called `name`; a missing column fails the test.
    [[nodiscard]] std::vector<double> column(std::string_view name) const;
};

/// The comma-separated fields of one line; a trailing comma gives a last, empty field.
std::vector<std::string> split_csv_line(const std::string& line);

/// Parses in the classic locale, correctly rounded, so a value written with max_digits10
/// digits (or by std::to_chars) comes back bit for bit. Anything but a whole number fails the test.
double parse_csv_number(const std::string& text);

/// Header and rows of `text`; a row that is not all numbers, or has the wrong width, fails the test.
CsvTable read_csv(const std::string& text);

}  // namespace workbook::testing
