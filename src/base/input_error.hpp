// The one exception type for bad input (a flag, a scene, a tableau file): chapter programs turn it into one
// line on stderr and exit status 2, before anything is written.
#pragma once

#include <stdexcept>
#include <string>

namespace cloth {

/// Bad input. The message names what was wrong and what is accepted.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cloth
