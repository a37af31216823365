// The one rule by which the book reads a number from text, a command-line value or an entry of a tableau file:
// the whole text, decimal (`0.01`, `-2.5e-3`) or C99 hexadecimal (`0x1.8p-3`, exact to the last bit), finite and
// in the normal range of a double. Everything else is refused saying why, so that one number means the same thing
// wherever it is typed.
#pragma once

#include <string>

namespace cloth {

/// Strict number parsing: the whole text must be a finite number in the normal range of a double (a number too
/// small to represent normally, subnormal or rounded to zero, is refused saying so). Throws InputError otherwise.
double parse_number(const std::string& text);

/// A whole number in base 10, as a 64-bit integer; throws InputError when the text is not one or overflows.
long long parse_integer(const std::string& text);

/// parse_integer bounded: throws InputError "expected a whole number from `low` to `high`, got '...'" outside.
long long parse_count(const std::string& text, long long low, long long high);

}  // namespace cloth
