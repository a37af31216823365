// Memory and number-range checks of a run before it starts, for program/limits.hpp.
#include "program/limits.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

namespace cloth {

namespace {

// What the program maps already (code, libraries, heap): the first field of /proc/self/statm, in pages.
double mapped_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0;
  statm >> pages;
  return pages * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

std::string format_bytes(double bytes) {
  if (bytes >= 1e12) return format_number(bytes / 1e12, 3) + " TB";
  if (bytes >= 1e9) return format_number(bytes / 1e9, 3) + " GB";
  if (bytes >= 1e6) return format_number(bytes / 1e6, 3) + " MB";
  return format_number(bytes / 1e3, 3) + " kB";
}

MemoryLimit memory_limit() {
  const double physical =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  MemoryLimit limit{0.75 * physical, "3/4 of this machine's " + format_bytes(physical) + " of memory"};
  rlimit address_space{};
  if (::getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
    const double left = static_cast<double>(address_space.rlim_cur) - mapped_bytes();
    if (left < limit.bytes)
      limit = {std::max(left, 0.0), "what the address-space limit (ulimit -v) of " +
                                        format_bytes(static_cast<double>(address_space.rlim_cur)) +
                                        " leaves beside the program"};
  }
  return limit;
}

void require_memory(double bytes, const std::string& flag, const std::string& what, const std::string& advice) {
  const MemoryLimit limit = memory_limit();
  if (bytes <= limit.bytes) return;
  throw InputError(flag + ": " + what + " needs about " + format_bytes(bytes) + ", more than the " +
                   format_bytes(limit.bytes) + " a run may use (" + limit.source + ")" + advice);
}

double explicit_bytes_per_particle() { return 8e3; }

double implicit_bytes_per_particle(long long particles) {
  return 16e3 * (1 + std::log2(std::max(1.0, static_cast<double>(particles) / 1e4)) / 4);
}

double sundials_klu_bytes_per_particle(long long particles) {
  // Largest resident sizes of ch09_sundials_benchmark (CVODE BDF, KLU) over its first steps: 41 MB at 30x30,
  // 122 MB at 50x50, 276 MB at 70x70, 728 MB at 100x100, above 2.1 GB at 150x150, so 45, 49, 56, 73 and more than
  // 95 kB a particle: KLU's fill of the 6n system grows faster than the implicit methods' n log n. With a margin.
  return 48e3 * (1 + std::sqrt(static_cast<double>(particles) / 1e4));
}

namespace {

// The memory check of a recorded run: the scene and the method (`bytes_per_particle`), the energy samples of a
// fixed-step run (one per step), the frames (at most one per step, or every frame asked for when interpolated).
void check_run_memory(const SceneParams& scene, const RunSettings& settings, double bytes_per_particle,
                      bool interpolated, const std::string& frames_flag, int runs_held) {
  const auto particles = static_cast<double>(scene.grid.M) * scene.grid.N;
  const auto steps = interpolated ? 0.0 : static_cast<double>(step_count(settings));
  const auto frames = static_cast<double>(interpolated ? settings.frames : frame_count(settings));
  const double model = runs_held * particles * bytes_per_particle;
  const double samples = interpolated ? 0.0 : runs_held * (steps + 1) * sizeof(EnergySample);
  const double recorded_frames = runs_held * (frames + 1) * (3 * particles * sizeof(double) + sizeof(Frame));
  const double total = model + samples + recorded_frames;
  const std::string grid = std::to_string(scene.grid.M) + "x" + std::to_string(scene.grid.N);
  if (model >= samples && model >= recorded_frames)
    require_memory(total, "--grid", "a run on a " + grid + " grid", ": expected a smaller grid");
  else if (samples >= recorded_frames)
    require_memory(total, "--t-end",
                   "a run of " + format_number(steps, 3) + " steps (--t-end / --dt), one energy sample each,",
                   ": expected a shorter --t-end or a larger --dt");
  else
    require_memory(total, frames_flag, "a run recording " + format_number(frames + 1, 6) + " frames of a " + grid +
                                           " grid", ": expected fewer frames or a smaller grid");
}

}  // namespace

void require_run_memory(const SceneParams& scene, const RunSettings& settings, double bytes_per_particle,
                        const std::string& frames_flag, int runs_held) {
  check_run_memory(scene, settings, bytes_per_particle, false, frames_flag, runs_held);
}

void require_interpolated_run_memory(const SceneParams& scene, const RunSettings& settings,
                                     double bytes_per_particle) {
  check_run_memory(scene, settings, bytes_per_particle, true, "--frames", 1);
}

void require_representable(const SceneParams& scene, const RunSettings& settings) {
  const SceneParams& p = scene;
  const RunSettings& run = settings;
  // Quantities the model squares must stay well inside the doubles: 1e150 squared is 1e300.
  constexpr double largest = 1e150;
  constexpr double largest_energy = 1e300;
  const double d = p.grid.d;
  const double extent = d * std::hypot(p.grid.M - 1, p.grid.N - 1);
  // The fastest initial speed: v0 plus the far edge's share of the swing, w (N-1) d.
  const double swing = std::abs(p.initial_swing) * (p.grid.N - 1) * d;
  const double v0 = std::abs(p.initial_velocity_z) + swing;
  const std::string speed_flag = swing > std::abs(p.initial_velocity_z) ? "--swing" : "--v0";
  const std::string speed_value = speed_flag == "--swing" ? format_number(p.initial_swing) + " rad/s"
                                                          : format_number(p.initial_velocity_z) + " m/s";
  const double T = run.t_end;
  const auto refuse = [](const std::string& flag, const std::string& what) {
    throw InputError(flag + ": " + what);
  };
  if (d * d < DBL_MIN)
    refuse("--spacing", format_number(d) + " is too small for the model's arithmetic: squared distances (d^2) "
                        "would fall below the smallest normal double, 2.2e-308; expected a spacing >= 1.5e-154 m");
  // The driver's divergence bound R = 10 (L + |v0| T + g T^2 / 2) + 1 is squared at every step.
  const double fall = 0.5 * p.gravity * T * T;
  if (10 * (extent + v0 * T + fall) + 1 > largest) {
    if (extent >= v0 * T && extent >= fall)
      refuse("--spacing", format_number(d) + " makes the cloth " + format_number(extent) +
                              " m wide, too large to square in a double; expected a cloth narrower than 1e149 m");
    if (v0 * T >= fall)
      refuse(speed_flag, speed_value + " carries the cloth " + format_number(v0 * T) +
                             " m in --t-end, too far to square in a double; expected |v0| T below 1e149 m");
    refuse("--t-end", format_number(T) + " s lets the cloth fall " + format_number(fall) +
                          " m, too far to square in a double; expected g T^2 / 2 below 1e149 m");
  }
  const double particles = static_cast<double>(p.grid.M) * p.grid.N;
  const double kinetic = 0.5 * p.mass * v0 * v0 * particles;
  if (!(kinetic <= largest_energy)) {
    if (v0 * v0 >= p.mass * particles)
      refuse(speed_flag, speed_value + " gives a kinetic energy of " + format_number(kinetic) +
                             " J at t = 0, beyond what the model's doubles hold (1e300); expected a smaller |" +
                             speed_flag.substr(2) + "|");
    refuse("--mass", format_number(p.mass) + " kg gives a kinetic energy of " + format_number(kinetic) +
                         " J at t = 0, beyond what the model's doubles hold (1e300); expected a smaller mass");
  }
  const double bound = 10 * (extent + v0 * T + fall) + 1;
  if (!(p.stiffness * bound * bound * particles <= largest_energy))
    refuse("--K", format_number(p.stiffness) + " N/m gives spring energies 1/2 K l^2 beyond what the model's doubles "
                  "hold (1e300) at the lengths the run may reach; expected a smaller K");
  if (!(p.mass * p.gravity * bound * particles <= largest_energy))
    refuse("--mass", format_number(p.mass) + " kg gives gravity energies m g z beyond what the model's doubles hold "
                     "(1e300) at the heights the run may reach; expected a smaller mass");
  if (!(p.stiffness / p.mass <= largest_energy))
    refuse("--mass", format_number(p.mass) + " kg with K = " + format_number(p.stiffness) +
                         " N/m gives omega^2 = K / m = " + format_number(p.stiffness / p.mass) +
                         " s^-2, beyond what the model's doubles hold (1e300); expected a larger mass or a smaller K");
}

}  // namespace cloth
