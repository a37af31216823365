// Safe reading of small text input files, for base/text_file.hpp.
#include "base/text_file.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cloth {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// Closes a file descriptor at scope exit.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  // Appended piece by piece: GCC 12 gives a false -Wrestrict on "literal" + std::string&& (GCC bug 105329).
  std::string shown = "'";
  shown.append(escaped(path)).append("'");
  // stat() first: opening a FIFO would block until a writer comes, and a device may never end.
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw InputError(shown + ": cannot read (" + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode)) throw InputError(shown + " is " + kind_of(info.st_mode) + ": expected a regular text file");
  // O_NONBLOCK: should the path have become a FIFO since the stat, the open returns at once; fstat then says so.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) throw InputError(shown + ": cannot read (" + std::strerror(errno) + ")");
  if (::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode))
    throw InputError(shown + " is " + kind_of(info.st_mode) + ": expected a regular text file");
  if (static_cast<std::size_t>(info.st_size) > max_bytes)
    throw InputError(shown + " has " + std::to_string(info.st_size) + " bytes: expected a text file of at most " +
                     std::to_string(max_bytes) + " bytes");
  // Read at most max_bytes + 1, whatever the size said: a file that grows meanwhile is still caught.
  std::string text(max_bytes + 1, '\0');
  std::size_t length = 0;
  while (length < text.size()) {
    const ssize_t got = ::read(file.fd, text.data() + length, text.size() - length);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputError(shown + ": cannot read (" + std::strerror(errno) + ")");
    }
    length += static_cast<std::size_t>(got);
  }
  if (length > max_bytes)
    throw InputError(shown + " has more than " + std::to_string(max_bytes) + " bytes: expected a text file of at most " +
                     std::to_string(max_bytes) + " bytes");
  text.resize(length);
  int line = 1, column = 1;
  for (const char ch : text) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte == '\n') {
      ++line;
      column = 1;
      continue;
    }
    if (!((byte >= 0x20 && byte < 0x7f) || byte == '\t' || byte == '\r'))
      throw InputError(escaped(path) + ":" + std::to_string(line) + ":" + std::to_string(column) + ": byte '" +
                       escaped(std::string_view(&ch, 1)) + "' is not printable text: expected a plain ASCII text file");
    ++column;
  }
  return text;
}

}  // namespace cloth
