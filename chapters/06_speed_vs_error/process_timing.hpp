// How Chapter 6's comparison with Boost.Odeint times whole programs: each run as a child process, its processor
// time the user and system time the operating system reports when it ends (start-up and output included), beside
// the wall clock. Timing inside one process is program/timing.hpp's; the appendix on measuring says why both.
#pragma once

#include "base/input_error.hpp"
#include "program/timing.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

extern char** environ;

namespace ch06 {

// Seconds of one run: wall, and processor time (the thread's in this process, user + system for a child).
struct Seconds {
  double wall = 0, cpu = 0;
};

// Runs a program to its end; returns its wall and CPU (user + system) seconds. Throws when it fails.
inline Seconds time_process(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  const double start = cloth::wall_seconds();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw cloth::InputError("cannot run " + args[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  const double wall = cloth::wall_seconds() - start;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw cloth::InputError(args[0] + " did not finish with status 0");
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return {wall, seconds(usage.ru_utime) + seconds(usage.ru_stime)};
}

// The fastest of `runs` timings, and the slowest CPU time among them: the spread says how far one timing on a
// shared computer can be from the best.
struct Timings {
  Seconds best{INFINITY, INFINITY};
  double slowest_cpu = 0;
  void add(const Seconds& s) {
    best.wall = std::min(best.wall, s.wall);
    best.cpu = std::min(best.cpu, s.cpu);
    slowest_cpu = std::max(slowest_cpu, s.cpu);
  }
};

inline Timings best_of(int runs, const std::function<Seconds()>& once) {
  Timings t;
  for (int k = 0; k < runs; ++k) t.add(once());
  return t;
}

}  // namespace ch06
