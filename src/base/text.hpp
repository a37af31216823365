// Text that came from outside the program (a command-line value, a line of a tableau file) shown safely in a
// message, and a name read from a file reduced to something that can only ever be one plain file name.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cloth {

/// `text` with every byte that is not printable ASCII written as an escape (`\n`, `\t`, `\xNN`), so that a message
/// quoting it is one line of plain text whatever the input held: no raw control bytes reach the terminal.
std::string escaped(std::string_view text);

/// `name` reduced to a safe file name: letters, digits, '.', '-' and '_' kept, every other byte replaced by '_',
/// no leading '.', at most `max_length` characters; an empty result becomes `fallback`. The result can never
/// name a parent folder, a subfolder or a hidden file, so a path built from it stays inside its folder.
std::string safe_file_name(std::string_view name, std::size_t max_length = 48, std::string_view fallback = "unnamed");

}  // namespace cloth
