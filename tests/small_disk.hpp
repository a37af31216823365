// A small disk for the full-disk tests: a 64 KiB tmpfs mounted on a scratch folder for the length of a test.
// Mounting needs root (CAP_SYS_ADMIN); where the system refuses, the tests that need it say so and skip.
#pragma once

#include "program_runner.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <sys/mount.h>

namespace cloth_test {

/// A small disk: a 64 KiB tmpfs mounted on a fresh folder, unmounted at scope exit. mounted() is false where the
/// system does not let the tests mount one (not root, or no CAP_SYS_ADMIN in a container); why() says why.
class SmallDisk {
 public:
  SmallDisk() {
    if (::mount("tmpfs", scratch_.path().c_str(), "tmpfs", 0, "size=64k") == 0) mounted_ = true;
    else why_ = std::strerror(errno);
  }
  ~SmallDisk() {
    if (mounted_) ::umount2(scratch_.path().c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;
  [[nodiscard]] bool mounted() const { return mounted_; }
  [[nodiscard]] const std::string& why() const { return why_; }
  [[nodiscard]] const fs::path& path() const { return scratch_.path(); }

 private:
  ScratchDir scratch_;
  bool mounted_ = false;
  std::string why_;
};

}  // namespace cloth_test
