// printf's %g behind a std::string, for base/format_number.hpp.
#include "base/format_number.hpp"

#include <cstdio>

namespace cloth {

std::string format_number(double x, int significant_digits) {
  char buf[64];  // %.17g of any double takes at most 24 characters
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, x);
  return buf;
}

}  // namespace cloth
