// A chapter program as a child process the test can watch and signal: fork and exec (optionally through a shell,
// for `ulimit`), stdout and stderr captured in files, and a wait with a time guard. The end-to-end tests of
// interrupted runs and memory limits are built on it; program_runner.hpp runs the programs that need neither.
#pragma once

#include "program_runner.hpp"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace cloth_test {

/// A started program: its process id and the files its stdout and stderr go to.
struct Child {
  pid_t pid = -1;
  fs::path out, err;
};

/// Starts build/bin/<program> with `args` in folder `cwd`. With a `shell_prefix` ("ulimit -v 400000;") the program
/// is run by /bin/sh after the prefix, through exec, so that the shell's process is the program's. Its stderr
/// goes to a file beside `cwd`, or to `stderr_to` when given (a terminal, to see what a reader sees).
inline Child spawn_chapter(const std::string& program, const std::vector<std::string>& args, const fs::path& cwd,
                           const std::string& shell_prefix = "", const fs::path& stderr_to = {}) {
  Child child;
  child.out = cwd.parent_path() / (cwd.filename().string() + ".stdout");
  child.err = stderr_to.empty() ? cwd.parent_path() / (cwd.filename().string() + ".stderr") : stderr_to;
  std::vector<std::string> words;
  if (shell_prefix.empty()) {
    words.push_back(program_path(program).string());
    words.insert(words.end(), args.begin(), args.end());
  } else {
    // Appended piece by piece: GCC 12 gives a false -Wrestrict on "literal" + std::string&& (GCC bug 105329).
    std::string command = shell_prefix;
    command.append(" exec ").append(shell_quote(program_path(program).string()));
    for (const std::string& a : args) command.append(" ").append(shell_quote(a));
    words = {"/bin/sh", "-c", command};
  }
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  child.pid = ::fork();
  if (child.pid == 0) {  // the child: only async-signal-safe calls until exec
    const int out = ::open(child.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(child.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(125);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(126);
  }
  return child;
}

/// Waits for the child to end: its exit status, 128 + n when signal n ended it (as a shell reports it), or 124
/// when it was still running after `time_guard_seconds` (it is then killed: a hang fails the test, it does not
/// hang the suite). Given `cpu_seconds`, it is set to the processor time (user and system) the child used in all.
inline int wait_for(const Child& child, double time_guard_seconds = 60, double* cpu_seconds = nullptr) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(time_guard_seconds);
  for (;;) {
    int raw = 0;
    rusage usage{};
    const pid_t done = ::wait4(child.pid, &raw, WNOHANG, &usage);
    if (done == child.pid) {
      if (cpu_seconds != nullptr)
        *cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
      return WIFEXITED(raw) ? WEXITSTATUS(raw) : WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : -1;
    }
    if (done < 0) return -1;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(child.pid, SIGKILL);
      ::waitpid(child.pid, &raw, 0);
      return 124;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
}

/// The processor time (user and system, to the kernel's tick of 10 ms) a running child has used so far, read
/// from /proc/<pid>/stat; -1 when it cannot be read. With wait_for's total, it gives the processor time a program
/// spent after a signal: unlike the wall-clock time, it does not grow while a loaded machine keeps the program
/// waiting for a processor.
inline double cpu_seconds_so_far(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  std::getline(in, stat);
  const auto end_of_name = stat.rfind(')');  // the program's name, in parentheses, may hold spaces
  if (end_of_name == std::string::npos) return -1;
  std::istringstream fields(stat.substr(end_of_name + 1));
  std::string field;
  long long utime = -1, stime = -1;
  // After the name: state (field 3) ... utime (field 14) and stime (field 15), in clock ticks.
  for (int k = 3; k <= 15 && fields >> field; ++k) {
    if (k == 14) utime = std::stoll(field);
    if (k == 15) stime = std::stoll(field);
  }
  if (utime < 0 || stime < 0) return -1;
  return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

/// Polls every half millisecond until `path` exists; false when the child ended first or `seconds` passed.
inline bool wait_until_exists(const Child& child, const fs::path& path, double seconds = 60) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(path)) return true;
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(child.pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid != 0)
      return fs::exists(path);
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  return false;
}

/// Runs a program to its end as a child (see spawn_chapter) and collects status, stdout and stderr.
inline ProgramRun run_child(const std::string& program, const std::vector<std::string>& args, const fs::path& cwd,
                            const std::string& shell_prefix = "", double time_guard_seconds = 60) {
  const Child child = spawn_chapter(program, args, cwd, shell_prefix);
  ProgramRun run;
  run.status = wait_for(child, time_guard_seconds);
  run.out = read_text(child.out);
  run.err = read_text(child.err);
  std::error_code ec;
  fs::remove(child.out, ec);
  fs::remove(child.err, ec);
  return run;
}

}  // namespace cloth_test
