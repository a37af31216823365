// Prints the flags every program shares as Markdown tables for the book's appendix on the programs, each from the
// one place that declares it: `common` the common flags (the table in src/program/command_line.cpp, with their
// defaults), `method` Newton's flags and the iterative methods' (cloth::NewtonFlags and cloth::IterationFlags).
#include "program/command_line.hpp"
#include "program/method_flags.hpp"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  const std::string which = argc == 2 ? argv[1] : "";
  if (which == "common") {
    // A command line with no chapter flags accepts every common flag at its declared default.
    const cloth::CommandLine cli("PROGRAM", "");
    std::string text = cli.markdown_reference();
    // The table is every program's, not one program's: its defaults are the declared ones, and `--out`'s is the
    // program's own name.
    const auto replace = [&text](const std::string& from, const std::string& to) {
      if (const auto at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
    };
    replace("| default here |", "| default |");
    replace("`./PROGRAM`", "a folder named after the program, in the current directory");
    std::cout << text;
    return 0;
  }
  if (which == "method") {
    cloth::CommandLine cli("PROGRAM", "");
    cli.use_common({});
    cloth::NewtonFlags newton;
    newton.add_to(cli);
    cloth::IterationFlags iterations;
    iterations.add_to(cli);
    // markdown_reference prints the (here empty) common table first; the method flags' table follows it.
    const std::string text = cli.markdown_reference();
    const auto own = text.find("\n|", text.find("\n\n"));
    std::cout << "| method flag | meaning |\n" << text.substr(text.find('\n', own + 1) + 1);
    return 0;
  }
  std::cerr << "flag_tables: expected one argument, common or method\n";
  return 2;
}
