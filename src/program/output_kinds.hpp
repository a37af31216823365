// Short names for the kinds of output file (program/output_spec.hpp), for the tables in which each program declares
// its files: with `using namespace cloth::output_kinds;` in the function that returns the table, a row reads
// {"summary.md", fragment, "the runs, as the page's table"}.
#pragma once

#include "program/output_spec.hpp"

namespace cloth::output_kinds {

inline constexpr OutputKind fragment = OutputKind::fragment;
inline constexpr OutputKind figure = OutputKind::figure_input;
inline constexpr OutputKind data = OutputKind::data;

}  // namespace cloth::output_kinds
