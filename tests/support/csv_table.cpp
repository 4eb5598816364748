#include "csv_table.hpp"

#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <charconv>
#include <limits>
#include <sstream>

namespace workbook::testing {

std::vector<double> CsvTable::column(std::string_view name) const {
    const auto found = std::ranges::find(names, name);
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
    double value = std::numeric_limits<double>::quiet_NaN();
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size()) FAIL("not a number in the CSV: \"" << text << '"');
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
