// The measuring half of Chapter 6's comparison with Boost.Odeint (odeint_peer.cpp is the program): the reader's
// program on the plain force loop, odeint and the core's engine on the core's forces, and the single-run programs
// of the chapters before, each run and timed here (odeint_timings.cpp).
#pragma once

#include "plain_fabric.hpp"
#include "process_timing.hpp"

#include "model/scene.hpp"
#include "program/fragment.hpp"

#include <string>
#include <vector>

namespace ch06 {

/// The report scene of `s` as the plain loop (plain_fabric.hpp) models it.
PlainFabric plain_fabric(const cloth::SceneParams& s);

/// The reader's program: odeint's runge_kutta4 (Ahnert & Mulansky 2011) with fixed steps h from 0 to T on the
/// plain loop; returns the final state y = (x, v).
std::vector<double> plain_rk4(const PlainFabric& fabric, double h, double T);

/// The lowest z of the positions x (x, y, z of each particle in turn, `size` numbers).
double lowest_z(const double* x, long size);

/// The flags that give another program this scene, step and horizon (`--dt` and `--t-end` last).
std::vector<std::string> scene_arguments(const cloth::SceneParams& s, double h, double T);

/// The first comparison: the reader's program (`self --program plain`) and the program `ch03` with its outputs
/// (written into `scratch`), each as a process, alternately: one configuration on each side, `runs` runs each.
struct Programs {
  Timings plain, ch03;
};
Programs time_programs(const std::string& self, const std::string& ch03, int runs,
                       const std::vector<std::string>& scene_args, const std::string& scratch);

/// The second comparison: odeint's runge_kutta4 and the core's tableau engine on the same forces, alternately, and
/// the reader's program in this process; where each ends (the lowest particle) shows that they solve one problem.
struct Integrators {
  Timings odeint, engine, plain;
  double z_odeint = 0, z_engine = 0, z_plain = 0;
};
Integrators time_integrators(const cloth::SceneParams& s, double h, double T, int runs);

/// What a program costs beyond its integration: one step of h = 0.01 s of each single-run program of the chapters
/// before this one (found in `bin`) on the same scene, as a whole process (start-up, the scene, the fastest rates
/// for run.txt, every output, written into `scratch`), the fastest of `runs`. A later chapter's program is timed on
/// its own page.
cloth::MarkdownTable one_step_table(const std::string& bin, const std::vector<std::string>& scene_args,
                                    const std::string& scratch, int runs);

}  // namespace ch06
