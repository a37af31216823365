// Output files that cannot be written in full are reported, never passed over: every writer throws OutputError
// naming the file and the system's reason, and a chapter program turns it into one line on stderr and exit
// status 4. A full disk is a 64 KiB tmpfs (small_disk.hpp); a folder that appears under a final name during the
// run is the other way a finished file can fail to take its place.
#include "program/output.hpp"
#include "program_runner.hpp"
#include "small_disk.hpp"

#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace cloth_test;

namespace {

/// The message of the OutputError that `write` throws, or "" if it throws none.
template <class Write>
std::string output_error_of(Write write) {
  try {
    write();
  } catch (const cloth::OutputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a writer that cannot open its file throws OutputError naming it") {
  const ScratchDir scratch;
  const std::string path = (scratch.path() / "missing_folder" / "run.txt").string();
  const std::string message = output_error_of([&] { cloth::write_key_values(path, {{"method", "rk4"}}); });
  CHECK(message == "cannot write '" + path + "': No such file or directory");
}

TEST_CASE("OutputFile: a folder that appears under the final name is a write error (exit 4), no file is left") {
  ScratchDir scratch;
  const fs::path path = scratch.path() / "run.txt";
  std::string message;
  try {
    cloth::OutputFile f(path.string());
    std::fputs("status = ok\n", f.get());
    fs::create_directory(path);  // in the way only now, after the run started
    f.commit();
  } catch (const cloth::OutputError& e) {
    message = e.what();
  }
  CHECK(message == "cannot write '" + path.string() + "': Is a directory");
  CHECK(fs::is_directory(path));
  CHECK(!fs::exists(scratch.path() / "run.txt.partial"));
}

#ifdef __linux__
TEST_CASE("a full disk (a 64 KiB tmpfs) is detected by every writer, naming the file and the reason") {
  const SmallDisk disk;
  if (!disk.mounted()) {
    MESSAGE("skipped: mounting a 64 KiB tmpfs is not permitted here (" << disk.why() << ")");
    return;
  }
  const std::vector<cloth::EnergySample> samples(3000, cloth::EnergySample{0.125, {1.0 / 3, -2.0 / 3, 1e-9}});
  const std::string dir = disk.path().string() + "/";
  const auto error_of = [](const std::function<void()>& write) {
    try {
      write();
    } catch (const cloth::OutputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Each writer alone on the empty disk, with more than 64 KiB to write; each leaves nothing behind.
  CHECK(error_of([&] { cloth::write_energy(dir + "energy.dat", samples); }) ==
        "cannot write '" + dir + "energy.dat': No space left on device");
  cloth::SceneParams big;
  big.grid = {60, 60, 0.1};  // 3600 lines of final.dat: more than 64 KiB even at rest
  const cloth::Scene large(big);
  cloth::Vector large_all(3 * large.particle_count());
  large.all_positions(large.initial_positions(), large_all);
  CHECK(error_of([&] {
          cloth::write_frames(dir + "frames.dat", large.grid(), std::vector<cloth::Frame>(10, {0.0, large_all}));
        }) == "cannot write '" + dir + "frames.dat': No space left on device");
  CHECK(error_of([&] { cloth::write_text(dir + "big.txt", std::string(70000, 'x')); }) ==
        "cannot write '" + dir + "big.txt': No space left on device");
  CHECK(error_of([&] { cloth::write_final(dir + "final.dat", large, large.initial_positions(),
                                          large.initial_velocities()); }) ==
        "cannot write '" + dir + "final.dat': No space left on device");
  std::vector<std::pair<std::string, std::string>> many(2000, {"key", std::string(40, 'v')});
  CHECK(error_of([&] { cloth::write_key_values(dir + "run.txt", many); }) ==
        "cannot write '" + dir + "run.txt': No space left on device");
  CHECK(entry_count(disk.path()) == 0);
}
#endif
