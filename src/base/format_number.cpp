// printf's %g behind a std::string, for base/format_number.hpp.
#include "base/format_number.hpp"

#include <cstdio>

namespace cloth {

std::string format_number(double x, int significant_digits) {
  char buf[64];  // %.17g of any double takes at most 24 characters
  // -0 + 0 is +0: a negative zero (a reader's "-0", or a product that rounded to zero) prints as "0".
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, x + 0.0);
  return buf;
}

}  // namespace cloth
