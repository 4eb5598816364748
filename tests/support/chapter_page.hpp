#pragma once
/// \file
/// Reading a chapter's page (chapters/<chapter>/chapter.md) in the checks that tie its text to
/// the code: a number the page prints is rebuilt from the computed value, formatted the way the
/// page prints it, and looked up in the page. Every failure names the page, and the number or
/// formula that was expected; what was found is the page's own text, quoted in the message.
///
/// The paths come from the caller (the checks pass WORKBOOK_SOURCE_DIR, which only their binary
/// defines), so this file needs nothing but the standard library and Catch2: it is built in the
/// student edition too.

#include <string>
#include <string_view>
#include <vector>

namespace workbook::testing {

/// The whole text of a file; one that cannot be read fails the test, naming the file.
std::string read_text_file(const std::string& path);

/// One chapter's page, read whole.
struct ChapterPage {
    std::string chapter;  ///< the chapter's name, as in its tags: "linear-impulse"
    std::string path;     ///< named in every failure, so that a message says which page
    std::string text;
};

/// Reads chapters/<chapter>/chapter.md below `source_dir`.
ChapterPage read_chapter_page(std::string_view source_dir, std::string_view chapter);

[[nodiscard]] bool contains(std::string_view text, std::string_view piece);

/// `text` with every run of white space made one space, so that a phrase or a test's name the
/// page wraps over two lines is still found.
std::string fold_white_space(const std::string& text);

/// The level-2 section whose heading carries `anchor` ("{#inelastic_worked_example}"): from
/// that heading up to the next "## " heading. A page without the anchor fails the test.
std::string section_with_anchor(const ChapterPage& page, std::string_view anchor);

/// The caption of the page's figure `figure` ("inelastic/clay-drop"): the quoted text after
/// `\figurefile{inelastic/clay-drop} `. A page without the figure fails the test.
std::string figure_caption(const ChapterPage& page, std::string_view figure);

/// A number as the pages print it: the stream's default notation with at most
/// `significant_digits` significant digits, so without trailing zeros (2, 0.5, 0.666666666667).
std::string page_number(double value, int significant_digits = 12);

/// A quantity as the pages print it inside a formula: 6\,\mathrm{kg\,m/s}.
std::string page_quantity(double value, std::string_view unit, int significant_digits = 12);

/// A fraction as the pages print it, \tfrac{2}{3}, after checking that the computed `value` is
/// numerator / denominator to within `tolerance`: the page's exact fraction must be the physics.
std::string page_fraction(double value, int numerator, int denominator, double tolerance);

/// A worked example, for check_worked_example: the formulas it must print, and what else in
/// its section may hold a digit without being a number (m_1, \tfrac12, "step 3").
struct WorkedExample {
    std::string anchor;                       ///< of its heading: "{#inelastic_worked_example}"
    std::vector<std::string> formulas;        ///< built from the computed numbers with page_number & co.
    std::vector<std::string> symbolic_text;   ///< removed as written, before the patterns
    std::vector<std::string> symbolic_patterns;  ///< ECMAScript regular expressions, removed in order
};

/// Every formula of `example` must stand in its section. Then, with the formulas, the anchor, the
/// symbolic text and the symbolic patterns removed, no digit may be left: a number added to the
/// example without a check fails here, quoting its line.
void check_worked_example(const ChapterPage& page, const WorkedExample& example);

/// A quantity with a unit (a digit, then \,\mathrm{...}) is a computed number, so it belongs in
/// the checked worked example (from `anchor` to the next "## " heading); one anywhere else on the
/// page fails the test, quoting it.
void check_units_only_in_worked_example(const ChapterPage& page, std::string_view anchor);

/// Every public step test in `step_tests_path` (tests/steps/<chapter>.cpp), a TEST_CASE tagged
/// [<chapter>][step:N:some-name], must be named in backquotes under the page's heading
/// "### Step N · some name", so that a student reading a step sees which tests check it.
/// Returns how many step tests it found, for the caller to compare with the chapter's count.
int check_step_tests_named_under_their_steps(const ChapterPage& page, const std::string& step_tests_path);

}  // namespace workbook::testing
