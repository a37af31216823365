// Each program declares the files it writes once, here in the form of a list of OutputSpec: the name, what the
// file holds, and who reads it. The same list prepares --out before a run (prepare_declared_outputs), is printed by
// `--list-outputs`, and is what the build checks a run and the book's pages against (cmake/CheckOutputs.cmake): a
// file a run did not write, a file it wrote but did not declare, and a page including a file that is not a declared
// fragment each fail the build and a test.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// Who reads an output file.
enum class OutputKind {
  fragment,      ///< a table, sentence or transcript a page of the book includes (program/fragment.hpp)
  figure_input,  ///< data the chapter's gnuplot script draws
  data,          ///< a result kept for the reader (a run's run.txt, final.dat, ...), read by no page or figure
};

/// The kind's name as `--list-outputs` prints it: "fragment", "figure_input" or "data".
const char* output_kind_name(OutputKind kind);

/// One file a program writes: its path relative to `--out` ("report_runs.md", "full_K50_D0/run.txt"), its kind, and
/// what it holds, in a few words.
struct OutputSpec {
  // All three, always: a list of bare names ({"a.md", "b.dat"}) stays a list of names, not of declarations.
  OutputSpec(std::string name_, OutputKind kind_, std::string holds_)
      : name(std::move(name_)), kind(kind_), holds(std::move(holds_)) {}

  std::string name;
  OutputKind kind;
  std::string holds;
};

using OutputList = std::vector<OutputSpec>;

/// The model page's four files of one run (final.dat, energy.dat, frames.dat, run.txt), inside `folder` when it is
/// not empty: data, but for those named in `drawn` ("energy.dat"), which the chapter's figures draw.
OutputList run_output_specs(const std::string& folder = "", std::initializer_list<const char*> drawn = {});

/// `list` followed by `more`.
OutputList operator+(OutputList list, const OutputList& more);

/// The names of `list`, in order.
std::vector<std::string> output_names(const OutputList& list);

/// What `--list-outputs` prints: one line per file, `name<TAB>kind<TAB>holds`.
std::string output_listing(const OutputList& list);

/// prepare_outputs (program/output.hpp) for the declared files: `written` are this run's, `others` the files of the
/// program's other modes an earlier run may have left.
void prepare_declared_outputs(const std::string& dir, const OutputList& written, const OutputList& others = {});

}  // namespace cloth
