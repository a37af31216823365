// The terminal progress line of program/progress.hpp.
#include "program/progress.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <unistd.h>

namespace cloth {

ProgressCallback terminal_progress(const std::string& label) {
  if (::isatty(STDERR_FILENO) == 0) return {};
  using Clock = std::chrono::steady_clock;
  struct State {
    std::string label;
    Clock::time_point start = Clock::now(), next_draw = start + std::chrono::seconds(2);
    bool drawn = false;
  };
  auto state = std::make_shared<State>();
  state->label = label;
  return [state](long long done, long long total, bool finished) {
    const Clock::time_point now = Clock::now();
    if (finished) {
      if (state->drawn) std::fprintf(stderr, "\r%*s\r", 78, "");  // clear the line for what follows
      state->drawn = false;
      return;
    }
    if (now < state->next_draw || total <= 0) return;
    state->next_draw = now + std::chrono::milliseconds(250);
    const double spent = std::chrono::duration<double>(now - state->start).count();
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const double left = fraction > 0 ? spent * (1 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r%s: step %lld of %lld (%.0f %%), %.0f s spent, about %.0f s left  ", state->label.c_str(),
                 done, total, 100 * fraction, spent, left);
    std::fflush(stderr);
    state->drawn = true;
  };
}

}  // namespace cloth
