// The book's tables of methods, made from the method registry: Chapter 3's explicit Runge-Kutta rows and Chapter
// 9's implicit ones. Each row's description is the registry's; what the tableau decides (stages, order, stiff
// accuracy, R(infinity), stability) is computed from it (analysis/tableau_properties.hpp). A chapter program
// writes them as fragments, so a new row of the registry appears in the book by itself.
#pragma once

#include "program/fragment.hpp"

namespace cloth {

/// Every explicit_runge_kutta row of the registry: name, stages, order, description.
MarkdownTable explicit_method_table();

/// Every row Newton's method runs (newton_methods(): the diagonally implicit tableaus and the multistep rows):
/// name, stages, order, stiffly accurate, R(infinity), stability, description. A multistep row has no tableau:
/// its order is the registry's claim, and the columns a tableau decides are left empty.
MarkdownTable implicit_method_table();

}  // namespace cloth
