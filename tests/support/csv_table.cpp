#include "csv_table.hpp"

#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <limits>
#include <locale>
#include <sstream>

namespace workbook::testing {

std::vector<double> CsvTable::column(std::string_view name) const {
    const auto found = std::find(names.begin(), names.end(), name);
    REQUIRE(found != names.end());
    const auto index = static_cast<std::size_t>(found - names.begin());
    std::vector<double> values;
    for (const auto& row : rows) values.push_back(row.at(index));
    return values;
}

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

double parse_csv_number(const std::string& text) {
    // What std::to_chars writes for the values that are not numbers; a stream reads none of them.
    if (text == "nan" || text == "-nan") return std::numeric_limits<double>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
    // A stream in the classic locale, not std::from_chars: libc++ reads a double with
    // from_chars only from LLVM 20 on (Xcode 26), and every C++ library's stream reads
    // digits the same, correctly rounded, whatever the student's locale.
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double value = std::numeric_limits<double>::quiet_NaN();
    in >> std::noskipws >> value;
    if (in.fail() || in.peek() != std::char_traits<char>::eof()) FAIL("not a number in the CSV: \"" << text << '"');
    return value;
}

CsvTable read_csv(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    CsvTable table;
    REQUIRE(static_cast<bool>(std::getline(in, line)));
    table.names = split_csv_line(line);
    while (std::getline(in, line)) {
        std::vector<double> row;
        for (const std::string& field : split_csv_line(line)) row.push_back(parse_csv_number(field));
        if (row.size() != table.names.size()) FAIL("CSV row of " << row.size() << " fields under " << table.names.size() << " columns: " << line);
        table.rows.push_back(std::move(row));
    }
    return table;
}

}  // namespace workbook::testing
