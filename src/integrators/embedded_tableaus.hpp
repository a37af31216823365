// The embedded Runge-Kutta pairs of Chapter 8: two weight rows over one set of stages, whose difference estimates
// the local error of a step.
#pragma once

#include "integrators/butcher_tableau.hpp"

#include <string>
#include <vector>

namespace cloth {

/// The built-in pairs, low order first: heun_euler 2(1), bs32 3(2), rkf45 4(5), cash_karp 5(4), dopri5 5(4),
/// tsit5 5(4). The first number is the order of the row that advances the solution (b), the second that of b-hat.
const std::vector<ButcherTableau>& embedded_tableaus();

/// A built-in pair by name, or else a tableau file by path. Throws InputError listing the accepted names when
/// neither exists, naming the line that is wrong in a file, or when the tableau has no 'bhat' row.
ButcherTableau embedded_tableau_from_argument(const std::string& name_or_path);

}  // namespace cloth
