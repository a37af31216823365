// Escaping for messages and safe file names, for base/text.hpp.
#include "base/text.hpp"

#include <cstdio>

namespace cloth {

std::string escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte >= 0x20 && byte < 0x7f && byte != '\\') out += ch;
    else if (byte == '\\') out += "\\\\";
    else if (byte == '\n') out += "\\n";
    else if (byte == '\t') out += "\\t";
    else if (byte == '\r') out += "\\r";
    else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    }
  }
  return out;
}

std::string safe_file_name(std::string_view name, std::size_t max_length, std::string_view fallback) {
  std::string out;
  for (const char ch : name) {
    if (out.size() >= max_length) break;
    const bool plain = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                       ch == '-' || ch == '_' || ch == '.';
    if (out.empty() && ch == '.') continue;  // no hidden file, no "." or ".."
    out += plain ? ch : '_';
  }
  return out.empty() ? std::string(fallback) : out;
}

}  // namespace cloth
