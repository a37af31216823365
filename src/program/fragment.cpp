// Fragments are written like every other output (program/output.hpp): under a temporary name, renamed when whole.
// A program declares them with its other outputs (prepare_outputs) before it runs.
#include "program/fragment.hpp"

#include "program/build_info.hpp"
#include "program/output.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace cloth {

namespace {

std::string escape_cell(const std::string& cell) {
  std::string escaped;
  for (const char c : cell) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

std::string row_line(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const std::string& cell : cells) {
    line += ' ';  // appended piece by piece: GCC 12 misreads " " + std::string as an overlapping copy
    line += escape_cell(cell);
    line += " |";
  }
  line += '\n';
  return line;
}

}  // namespace

MarkdownTable::MarkdownTable(std::vector<std::string> header, std::string alignment)
    : header_(std::move(header)), alignment_(std::move(alignment)) {
  if (alignment_.empty()) alignment_.assign(header_.size(), 'l');
  if (alignment_.size() != header_.size() || alignment_.find_first_not_of("lr") != std::string::npos)
    throw std::invalid_argument("MarkdownTable: alignment '" + alignment_ + "' needs one 'l' or 'r' per column");
}

void MarkdownTable::add_row(std::vector<std::string> cells) {
  if (cells.size() != header_.size())
    throw std::invalid_argument("MarkdownTable: a row of " + std::to_string(cells.size()) + " cells in a table of " +
                                std::to_string(header_.size()) + " columns");
  rows_.push_back(std::move(cells));
}

std::string MarkdownTable::markdown() const {
  std::string text = row_line(header_) + "|";
  for (const char a : alignment_) text += a == 'r' ? "---:|" : "---|";
  text += "\n";
  for (const auto& row : rows_) text += row_line(row);
  return text;
}

std::string measured_by_line(const std::string& command) {
  // An HTML block, so that docs/book.css can set it apart from the prose.
  return "<div class=\"measured\">Measured by `" + command + "`, compiled by " + compiler_description() + " with `" +
         compiler_flags() + "` (" + vector_instructions() + "), on " + processor_description() + ".</div>\n";
}

void write_table_fragment(const std::string& path, const MarkdownTable& table, const std::string& command) {
  write_text_fragment(path, table.markdown() + "\n" + measured_by_line(command));
}

void write_text_fragment(const std::string& path, const std::string& text) { write_text(path, text); }

std::string reader_command(int argc, const char* const* argv) {
  std::string program = argc > 0 ? argv[0] : "";
  std::string command = program.substr(program.find_last_of('/') + 1);
  for (int k = 1; k < argc; ++k) {
    const std::string argument = argv[k];
    if (argument == "--out") {
      ++k;  // and its value
      continue;
    }
    if (argument.rfind("--out=", 0) == 0) continue;
    command += " " + argument;
  }
  return command;
}

std::string format_fixed(double x, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  return buffer;
}

std::string format_significant(double x, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%#.*g", digits, x);
  std::string text = buffer;
  // '#' keeps the zeros, and also a point with nothing after it ("100."): that point goes.
  if (const auto point = text.find('.'); point != std::string::npos && point + 1 == text.size()) text.pop_back();
  return text;
}

}  // namespace cloth
