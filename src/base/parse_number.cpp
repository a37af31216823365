// Strict reading of numbers from text, for base/parse_number.hpp.
#include "base/parse_number.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>

namespace cloth {

namespace {

// strtod and strtoll skip leading blanks; a value with blanks around it is a quoting slip, so it is refused whole.
bool has_blank(const std::string& text) { return text.find_first_of(" \t\n\r\f\v") != std::string::npos; }

std::string quoted(const std::string& text) { return "'" + escaped(text) + "'"; }

}  // namespace

double parse_number(const std::string& text) {
  if (text.empty()) throw InputError("expected a number, got an empty value");
  if (has_blank(text)) throw InputError("expected a number, got " + quoted(text));
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) throw InputError("expected a number, got " + quoted(text));
  if (std::isnan(value) || (std::isinf(value) && errno != ERANGE))
    throw InputError("expected a finite number, got " + quoted(text));
  if (std::isinf(value))
    throw InputError(quoted(text) + " is too large to represent: expected a number below 1.8e308, the largest double");
  // strtod sets ERANGE when the number underflows, to a subnormal or to zero: refused, since it has lost digits
  // (and a subnormal slows every operation on it a hundredfold).
  if ((errno == ERANGE && value == 0) || (value != 0 && std::abs(value) < DBL_MIN))
    throw InputError(quoted(text) + " is too small to represent normally (below 2.2e-308, the smallest normal "
                     "double): expected 0 or a number of larger magnitude");
  return value + 0.0;  // -0 is 0
}

long long parse_integer(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || has_blank(text) || end != text.c_str() + text.size() || errno == ERANGE)
    throw InputError("expected a whole number, got " + quoted(text));
  return value;
}

long long parse_count(const std::string& text, long long low, long long high) {
  long long value = 0;
  try {
    value = parse_integer(text);
  } catch (const InputError&) {
    value = low - 1;  // refused below with the range, which says more than "a whole number"
  }
  if (value < low || value > high)
    throw InputError("expected a whole number from " + std::to_string(low) + " to " + std::to_string(high) +
                     ", got " + quoted(text));
  return value;
}

}  // namespace cloth
