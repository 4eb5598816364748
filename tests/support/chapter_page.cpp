#include "chapter_page.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

namespace workbook::testing {

namespace {

std::string remove_all(std::string text, std::string_view piece) {
    for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at)) text.erase(at, piece.size());
    return text;
}

/// The whole line of `text` around position `at`.
std::string line_at(const std::string& text, std::size_t at) {
    const std::size_t begin = text.rfind('\n', at);
    const std::size_t start = begin == std::string::npos ? 0 : begin + 1;
    const std::size_t end = text.find('\n', at);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

/// For a formula the example does not print: the line that prints the longest start of it
/// that ends at an " = " (its left-hand side, or the substitution before the result), so that
/// the message shows the number the page has where the computed one was expected.
std::string line_printing_instead(const std::string& example, const std::string& formula) {
    for (std::size_t equals = formula.rfind(" = "); equals != std::string::npos;
         equals = equals == 0 ? std::string::npos : formula.rfind(" = ", equals - 1)) {
        const std::size_t at = example.find(formula.substr(0, equals + 3));
        if (at != std::string::npos) return line_at(example, at);
    }
    return "(no line of the example starts the same way)";
}

}  // namespace

std::string read_text_file(const std::string& path) {
    std::ifstream in(path);
    INFO("reading " << path);
    REQUIRE(in.good());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ChapterPage read_chapter_page(std::string_view source_dir, std::string_view chapter) {
    ChapterPage page;
    page.chapter = chapter;
    page.path = std::string(source_dir) + "/chapters/" + page.chapter + "/chapter.md";
    page.text = read_text_file(page.path);
    return page;
}

bool contains(std::string_view text, std::string_view piece) { return text.find(piece) != std::string_view::npos; }

std::string fold_white_space(const std::string& text) { return std::regex_replace(text, std::regex(R"(\s+)"), " "); }

std::string section_with_anchor(const ChapterPage& page, std::string_view anchor) {
    const std::string& text = page.text;
    const std::size_t heading = text.find(anchor);
    INFO(page.path << ": looking for the section " << anchor);
    REQUIRE(heading != std::string::npos);
    const std::size_t begin = text.rfind("\n## ", heading);
    const std::size_t end = text.find("\n## ", heading);
    return text.substr(begin == std::string::npos ? 0 : begin, end == std::string::npos ? std::string::npos : end - begin);
}

std::string figure_caption(const ChapterPage& page, std::string_view figure) {
    const std::string image = "\\figurefile{" + std::string(figure) + "} \"";
    const std::size_t begin = page.text.find(image);
    INFO(page.path << " should show " << image);
    REQUIRE(begin != std::string::npos);
    const std::size_t caption = begin + image.size();
    return page.text.substr(caption, page.text.find('"', caption) - caption);
}

std::string page_number(double value, int significant_digits) {
    std::ostringstream out;
    out.precision(significant_digits);
    out << value;
    return out.str();
}

std::string page_quantity(double value, std::string_view unit, int significant_digits) {
    return page_number(value, significant_digits) + "\\,\\mathrm{" + std::string(unit) + "}";
}

std::string page_fraction(double value, int numerator, int denominator, double tolerance) {
    const std::string printed = "\\tfrac{" + std::to_string(numerator) + "}{" + std::to_string(denominator) + "}";
    INFO("the page prints " << printed << " for the computed " << page_number(value, 17));
    CHECK(std::abs(value - static_cast<double>(numerator) / static_cast<double>(denominator)) < tolerance);
    return printed;
}

void check_worked_example(const ChapterPage& page, const WorkedExample& example) {
    std::string text = section_with_anchor(page, example.anchor);
    for (const std::string& formula : example.formulas) {
        const bool printed = contains(text, formula);
        INFO(page.path << ": the worked example should print: " << formula);
        INFO("it prints instead: " << (printed ? std::string() : line_printing_instead(text, formula)));
        CHECK(printed);
    }

    // Only digits matter from here on: what is left once the checked formulas and the symbols
    // whose digits are no numbers (indices, \tfrac12, "step 3") are gone must hold none.
    for (const std::string& formula : example.formulas) text = remove_all(text, formula);
    text = remove_all(text, example.anchor);
    for (const std::string& symbolic : example.symbolic_text) text = remove_all(text, symbolic);
    for (const std::string& pattern : example.symbolic_patterns) text = std::regex_replace(text, std::regex(pattern), "");
    std::smatch leftover;
    if (std::regex_search(text, leftover, std::regex(R"([^\n]*[0-9][^\n]*)")))
        FAIL(page.path << ": the worked example prints a number no check covers, in: " << leftover.str());
}

void check_units_only_in_worked_example(const ChapterPage& page, std::string_view anchor) {
    const std::string& text = page.text;
    const std::size_t example_begin = text.find(anchor);
    {
        INFO(page.path << ": looking for the worked example " << anchor);
        REQUIRE(example_begin != std::string::npos);
    }
    const std::size_t example_end = text.find("\n## ", example_begin);
    const std::string outside = text.substr(0, example_begin) + (example_end == std::string::npos ? "" : text.substr(example_end));
    std::smatch unit;
    if (std::regex_search(outside, unit, std::regex(R"([0-9]\s*\\,\\mathrm\{[^}]*\})")))
        FAIL(page.path << ": a quantity with a unit appears outside the checked worked example: " << unit.str());
}

int check_step_tests_named_under_their_steps(const ChapterPage& page, const std::string& step_tests_path) {
    const std::string tests = read_text_file(step_tests_path);
    const std::regex test_case(R"re(TEST_CASE\("([^"]+)",\s*"\[)re" + page.chapter + R"re(\]\[step:([0-9]+):([a-z-]+)\])re");
    int found = 0;
    for (auto it = std::sregex_iterator(tests.begin(), tests.end(), test_case); it != std::sregex_iterator(); ++it) {
        ++found;
        const std::string name = (*it)[1].str();
        std::string title = (*it)[3].str();
        for (char& c : title)
            if (c == '-') c = ' ';
        const std::string heading = "### Step " + (*it)[2].str() + " \xC2\xB7 " + title;
        INFO(page.path << ": step heading: " << heading << "; test: " << name);
        const std::size_t begin = page.text.find(heading);
        REQUIRE(begin != std::string::npos);
        const std::size_t end = page.text.find("\n##", begin + heading.size());
        const std::string step_text = page.text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        CHECK(contains(fold_white_space(step_text), "`" + name + "`"));
    }
    return found;
}

}  // namespace workbook::testing
