// What a run may ask of the machine and of the model's numbers, checked before anything runs: the memory it will
// allocate against the memory there is, and the sizes at t = 0 (distances, energies) against what a double holds.
// A run outside either is bad input (exit status 2), refused naming the flag, never a crash halfway.
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"

#include <string>

namespace cloth {

/// The memory a run may use, and where that figure comes from.
struct MemoryLimit {
  double bytes;
  std::string source;  ///< "3/4 of this machine's 23.4 GB of memory", or the address-space limit (ulimit -v)
};

/// Three quarters of the physical memory (the rest is headroom for the system and for other programs), and no
/// more than what the address-space limit (ulimit -v, RLIMIT_AS) leaves beyond what the program already maps.
MemoryLimit memory_limit();

/// "1.2 TB", "12.3 GB", "456 MB", "789 kB".
std::string format_bytes(double bytes);

/// Throws InputError "<flag>: <what> needs about X, more than the Y a run may use (<source>)<advice>" when
/// `bytes` exceeds memory_limit().
void require_memory(double bytes, const std::string& flag, const std::string& what, const std::string& advice = "");

/// Memory of a scene, its force field and one method's vectors and matrices, per particle. Measured as the
/// largest resident size of the programs on grids of 10^4 and 4 10^4 particles (/usr/bin/time), with a margin;
/// the implicit methods' sparse factors fill in like n log n on a grid.
double explicit_bytes_per_particle();
double implicit_bytes_per_particle(long long particles);

/// Checks `runs_held` recorded runs of `settings` on `scene` whose results are held at once (each: the scene, an
/// energy sample per step, the frames) against memory_limit(), naming the flag whose share is largest: `--grid`,
/// `--t-end` (the samples; T / h steps), or `frames_flag` (`--frames`, or whatever set settings.frames).
void require_run_memory(const SceneParams& scene, const RunSettings& settings, double bytes_per_particle,
                        const std::string& frames_flag = "--frames", int runs_held = 1);

/// The same for a run that chooses its own steps (Chapter 8's adaptive driver): its frames are interpolated at
/// the settings.frames + 1 times asked for, all of them, whatever the steps; its energy samples, one per accepted
/// step, are not known before it runs and are not counted.
void require_interpolated_run_memory(const SceneParams& scene, const RunSettings& settings,
                                     double bytes_per_particle);

/// The memory of SUNDIALS' implicit integrators with KLU on the cloth's first-order system y = (x, v), 6n
/// unknowns, per particle: the sparse Jacobian, the Newton matrix I - gamma J and KLU's LU factors of it, beside
/// the integrator's vectors. Measured like the figures above (ch09_sundials_benchmark, CVODE BDF): the factors of
/// the 6n system fill in faster than the implicit methods' n log n, about like n^1.5.
double sundials_klu_bytes_per_particle(long long particles);


/// Refuses a scene and run whose numbers at t = 0 a double cannot hold, naming the flag: squared distances that
/// overflow (`--spacing`, and `--v0` and `--t-end` through the divergence bound R of the driver) or underflow
/// (`--spacing`), a kinetic energy that overflows (`--v0`, `--mass`), a spring or gravity energy at the scale of R
/// (`--K`, `--mass`), or omega^2 = K / m (`--K`, `--mass`).
void require_representable(const SceneParams& scene, const RunSettings& settings);

}  // namespace cloth
