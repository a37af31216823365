// The book's measured fragments (program/fragment.hpp) and the line naming the build that measured them
// (program/build_info.hpp): what a page includes must be a well-formed Markdown table, say which command and
// build measured it, and be written whole or not at all.
#include "program/build_info.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace cloth_test;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("a Markdown table has its header, one alignment mark per column, and its rows, '|' escaped") {
  cloth::MarkdownTable table({"K, D", "iterations", "outcome"}, "lrl");
  table.add_row({"50, 0", "3.00", "finishes"});
  table.add_row({"200, 20", "3.25", "a|b"});
  CHECK(table.markdown() ==
        "| K, D | iterations | outcome |\n"
        "|---|---:|---|\n"
        "| 50, 0 | 3.00 | finishes |\n"
        "| 200, 20 | 3.25 | a\\|b |\n");
}

TEST_CASE("a row of the wrong width and a wrong alignment are programming errors, refused") {
  cloth::MarkdownTable table({"a", "b"});
  CHECK_THROWS_AS(table.add_row({"1"}), std::invalid_argument);
  CHECK_THROWS_AS(table.add_row({"1", "2", "3"}), std::invalid_argument);
  CHECK_THROWS_AS(cloth::MarkdownTable({"a", "b"}, "l"), std::invalid_argument);
  CHECK_THROWS_AS(cloth::MarkdownTable({"a"}, "c"), std::invalid_argument);
}

TEST_CASE("a table fragment ends with one line naming the command, the compiler, the flags and the processor") {
  const ScratchDir scratch;
  cloth::MarkdownTable table({"k", "r_k"}, "rr");
  table.add_row({"0", "110"});
  const fs::path path = scratch.path() / "table.md";
  cloth::write_table_fragment(path.string(), table, "ch04_implicit_euler --report-runs");
  const std::string text = read_file(path);
  CHECK(text.rfind(table.markdown() + "\n", 0) == 0);  // the table first, then a blank line
  const std::string last = text.substr(table.markdown().size() + 1);
  CHECK(last == "<div class=\"measured\">Measured by `ch04_implicit_euler --report-runs`, compiled by " +
                    cloth::compiler_description() + " with `" + cloth::compiler_flags() + "` (" +
                    cloth::vector_instructions() + "), on " + cloth::processor_description() + ".</div>\n");
  CHECK(!fs::exists(path.string() + ".partial"));
}

TEST_CASE("the build is named by the compiler's own version, CMake's flags and /proc/cpuinfo's model name") {
#if defined(__clang__)
  CHECK(cloth::compiler_description() == "Clang " + std::to_string(__clang_major__) + "." +
                                             std::to_string(__clang_minor__) + "." +
                                             std::to_string(__clang_patchlevel__));
#elif defined(__GNUC__)
  CHECK(cloth::compiler_description() == "GCC " + std::to_string(__GNUC__) + "." + std::to_string(__GNUC_MINOR__) +
                                             "." + std::to_string(__GNUC_PATCHLEVEL__));
#endif
  // The flags of the build type are there (Release: -O3), the warnings are not.
  CHECK(!cloth::compiler_flags().empty());
  CHECK(cloth::compiler_flags().find("-W") == std::string::npos);
  // The processor: the first "model name" line of /proc/cpuinfo, read here independently.
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string expected = "an unnamed processor";
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      expected = line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
      break;
    }
  CHECK(cloth::processor_description() == expected);
}

TEST_CASE("the command a reader types leaves out the output folder, in both spellings") {
  const char* argv[] = {"/path/to/build/bin/ch04_implicit_euler", "--out", "build/plots/data/ch04", "--report-runs",
                        "--out=elsewhere", "--K", "200"};
  CHECK(cloth::reader_command(7, argv) == "ch04_implicit_euler --report-runs --K 200");
  const char* bare[] = {"ch01_springs"};
  CHECK(cloth::reader_command(1, bare) == "ch01_springs");
}

TEST_CASE("a fragment that cannot be written throws OutputError naming it, and leaves no file behind") {
  const ScratchDir scratch;
  const fs::path path = scratch.path() / "no_such_folder" / "sentence.md";
  CHECK_THROWS_AS(cloth::write_text_fragment(path.string(), "1.99"), cloth::OutputError);
  CHECK(!fs::exists(path));
}

TEST_CASE("a measured column keeps its significant figures: 3.0019 to three figures is 3.00, not 3") {
  CHECK(cloth::format_significant(3.001932, 3) == "3.00");
  CHECK(cloth::format_significant(0.04776961, 3) == "0.0478");
  CHECK(cloth::format_significant(-2.764605, 3) == "-2.76");
  CHECK(cloth::format_significant(4e4, 3) == "4.00e+04");
  CHECK(cloth::format_significant(1779.9e-3, 4) == "1.780");
  CHECK(cloth::format_significant(100, 3) == "100");  // no point left dangling
  CHECK(cloth::format_significant(0.000313, 3) == "0.000313");
}
