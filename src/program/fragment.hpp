// Fragments of the book: the tables, sentences and transcripts a chapter program measures, written as small
// Markdown files into its output folder. The chapter's page includes them when the book is built
// (`\include{doc} ch04_implicit_euler/report_runs.md`; Doxygen's EXAMPLE_PATH holds build/plots/data), so the
// book quotes exactly what the program measured, the way Eigen's documentation shows its examples' real output.
// A fragment is an output like any other: the program lists it in prepare_outputs() before it runs, and the
// chapter's cloth_add_plot() lists it under FRAGMENTS, so that the book's build fails when it is not written.
#pragma once

#include <string>
#include <vector>

namespace cloth {

/// A Markdown table: a header, then rows of as many cells. A cell is Doxygen Markdown (`code`, *emphasis*); a '|'
/// in it is escaped. Formulas (\f$ ... \f$) are not processed in an included file, so a number is written the
/// way the programs print it (1.4e-12).
class MarkdownTable {
 public:
  /// `alignment` has one letter per column, 'l' or 'r' (numbers read best right-aligned); empty: all left.
  explicit MarkdownTable(std::vector<std::string> header, std::string alignment = "");

  /// Appends a row; throws std::invalid_argument when it has not as many cells as the header.
  void add_row(std::vector<std::string> cells);

  /// The table as Markdown, one line per row, ending with a newline.
  [[nodiscard]] std::string markdown() const;

 private:
  std::vector<std::string> header_;
  std::string alignment_;
  std::vector<std::vector<std::string>> rows_;
};

/// Writes `table` to `path`, followed by one line naming what measured it: `command` (the program and its flags
/// as a reader would type them) and the build (cloth::build_description). Throws OutputError when the file
/// cannot be written in full.
void write_table_fragment(const std::string& path, const MarkdownTable& table, const std::string& command);

/// The line a measured fragment ends with: `command` (as a reader would type it) and the build that measured it.
/// write_table_fragment appends it; a fragment of several tables appends it once, after the last.
std::string measured_by_line(const std::string& command);

/// Writes `text` to `path` as it is: a sentence or a value for the page's prose, or a console transcript for
/// `\verbinclude`. Throws OutputError when the file cannot be written in full.
void write_text_fragment(const std::string& path, const std::string& text);

/// The command a reader would type to measure it again: the program's name and its arguments, without the
/// output folder (`--out DIR`), which is the build's business: `ch04_implicit_euler --report-runs`.
std::string reader_command(int argc, const char* const* argv);

/// `x` with `decimals` digits after the point ("3.00"), for columns whose digits should line up.
std::string format_fixed(double x, int decimals);

/// `x` to `digits` significant figures with its trailing zeros kept ("3.00", "0.0478", "4.00e+04", "100"): for
/// a measured column, where format_number's "3" would claim one figure where three were measured.
std::string format_significant(double x, int digits);

}  // namespace cloth
