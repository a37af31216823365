// One way to turn a number into text for messages, run.txt values and file names, so that every program prints
// the same value the same way: printf's %g with a chosen number of significant digits.
#pragma once

#include <string>

namespace cloth {

/// `x` as printf's "%.<significant_digits>g": the shortest of fixed and exponent notation, trailing zeros dropped
/// ("0.01", "1e-07", "200"); zero is "0" whatever its sign. The default of 6 digits is what %g and std::ostream print.
std::string format_number(double x, int significant_digits = 6);

}  // namespace cloth
