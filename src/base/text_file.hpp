// Reading a small text input file (a tableau, a scene) without trusting it: only a regular file is opened, its
// size is capped, and it must be printable text. A directory, a FIFO or a device is refused by name before it is
// opened, so that nothing blocks on a pipe or reads without end from /dev/zero.
#pragma once

#include <cstddef>
#include <string>

namespace cloth {

/// The whole content of the regular file at `path`. Throws InputError, the message starting with `path` (escaped),
/// when the file does not exist or cannot be read, is not a regular file (saying what it is: a folder, a FIFO, a
/// device, a socket), is larger than `max_bytes`, or holds a byte that is not printable text (ASCII from space to
/// '~', tab, newline, carriage return), naming its line and column and showing it escaped.
std::string read_text_file(const std::string& path, std::size_t max_bytes = 64 * 1024);

}  // namespace cloth
