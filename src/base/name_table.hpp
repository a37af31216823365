// The names of an enumerated setting (a linear solver, a Jacobian treatment, a Newton variant, a method family):
// one table per enum gives the name of a value, parses a name back, and lists the accepted names for messages,
// so that no program keeps its own list and every message lists the same names.
#pragma once

#include "base/input_error.hpp"

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cloth {

template <class Enum>
class NameTable {
 public:
  struct Entry {
    Enum value;
    const char* name;
  };

  /// `what` names the setting in messages ("linear solver"); `entries` gives every value once, in the order
  /// messages list them.
  NameTable(std::string what, std::initializer_list<Entry> entries) : what_(std::move(what)), entries_(entries) {}

  /// The value called `name`. Throws InputError "unknown linear solver 'qr': expected one of ldlt, ..." otherwise
  /// (the setting named by what()).
  [[nodiscard]] Enum parse(const std::string& name) const {
    for (const Entry& e : entries_)
      if (name == e.name) return e.value;
    throw InputError("unknown " + what_ + " '" + name + "': expected one of " + accepted());
  }

  /// The value called `name`, or nothing when the table has no such name (for a caller that tries several tables).
  [[nodiscard]] std::optional<Enum> find(const std::string& name) const {
    for (const Entry& e : entries_)
      if (name == e.name) return e.value;
    return std::nullopt;
  }

  /// The name of `value` ("?" for a value the table does not list, which a test rules out).
  [[nodiscard]] const char* name(Enum value) const {
    for (const Entry& e : entries_)
      if (e.value == value) return e.name;
    return "?";
  }

  /// Every name, joined by `separator`: "ldlt, ldu, cg, lu" for messages, "ldlt|ldu|cg|lu" for usage lines.
  [[nodiscard]] std::string accepted(const char* separator = ", ") const {
    std::string out;
    for (const Entry& e : entries_) {
      if (!out.empty()) out += separator;
      out += e.name;
    }
    return out;
  }

  [[nodiscard]] const std::string& what() const { return what_; }
  [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::string what_;
  std::vector<Entry> entries_;
};

}  // namespace cloth
