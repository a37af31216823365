// Chapter 10's projection study, measured (projection_runs.hpp): every program's ladder of steps against the
// spring model's motion at T, and each program's coarsest step to 1 cm and 1 mm timed in the same run (thread CPU
// time, median of 5 with the fastest and the slowest).
#include "projection_runs.hpp"

#include "study.hpp"

#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

std::string seconds_text(const Timing& t) {
  return format("%.3g (%.3g-%.3g)", t.median_cpu, t.fastest_cpu, t.slowest_cpu);
}

}  // namespace

Ladders run_ladders(const std::vector<Contender>& contenders, const Vector& truth, const std::string& dir,
                    const std::string& command) {
  Ladders measured(contenders.size());
  MarkdownTable runs({"program", "step h [s]", "steps", "largest error at T [m]"}, "lrrr");
  for (std::size_t c = 0; c < contenders.size(); ++c) {
    for (const long long n : contenders[c].steps) {
      Measured& m = measured[c][n];
      const Vector at_T = contenders[c].run(n);
      m.error = at_T.allFinite() ? largest_distance(at_T, truth) : NAN;  // NaN: the run failed
      throw_if_interrupted();
      std::printf("%-30s h = %.3g: error %.3g m\n", contenders[c].title.c_str(), T / static_cast<double>(n), m.error);
      runs.add_row({contenders[c].title, format_number(T / static_cast<double>(n), 3), std::to_string(n),
                    std::isfinite(m.error) ? format_number(m.error, 3) : "failed"});
      if (m.error <= levels[1]) break;  // finer steps would only cost more
    }
  }
  write_table_fragment(dir + "/projection_runs.md", runs, command);
  return measured;
}

void time_at_levels(const std::vector<Contender>& contenders, Ladders& measured, const std::string& dir,
                    const std::string& command) {
  std::string ratios;
  MarkdownTable fastest({"level", "program", "step h [s]", "largest error at T [m]",
                         "CPU s, median of 5 (fastest-slowest)"},
                        "rlrrr");
  const TimingPlan plan{5, 1, 1};
  for (const double level : levels) {
    const Measured* best_book = nullptr;
    const Measured* best_peer = nullptr;
    std::size_t book_index = 0, peer_index = 0;
    for (std::size_t c = 0; c < contenders.size(); ++c) {
      long long chosen = 0;
      for (const long long n : contenders[c].steps) {
        const auto it = measured[c].find(n);
        if (it != measured[c].end() && it->second.error <= level) {
          chosen = n;
          break;
        }
      }
      if (chosen == 0) {
        fastest.add_row({format_number(level), contenders[c].title, "", "not reached", ""});
        continue;
      }
      Measured& m = measured[c][chosen];
      if (!m.timed) {
        m.timing = time_runs([&] { (void)contenders[c].run(chosen); }, plan);
        m.timed = true;
        throw_if_interrupted();
      }
      fastest.add_row({format_number(level), contenders[c].title, format_number(T / static_cast<double>(chosen), 3),
                       format_number(m.error, 3), seconds_text(m.timing)});
      const Measured*& best = contenders[c].book ? best_book : best_peer;
      if (best == nullptr || m.timing.median_cpu < best->timing.median_cpu) {
        best = &m;
        (contenders[c].book ? book_index : peer_index) = c;
      }
    }
    if (best_book == nullptr || best_peer == nullptr) {
      ratios += format("- %s: %s.\n", format_number(level).c_str(),
                       best_book == nullptr ? "no method of the book reaches it" : "no peer reaches it");
      continue;
    }
    const Timing& b = best_book->timing;
    const Timing& q = best_peer->timing;
    ratios += format("- %s m: %s %.3g s against %s %.3g s: **%.2f x** (from %.2f to %.2f over the spread of "
                     "both).\n",
                     format_number(level).c_str(), contenders[book_index].title.c_str(), b.median_cpu,
                     contenders[peer_index].title.c_str(), q.median_cpu, b.median_cpu / q.median_cpu,
                     b.fastest_cpu / q.slowest_cpu, b.slowest_cpu / q.fastest_cpu);
  }
  std::printf("%s", ratios.c_str());
  write_text_fragment(dir + "/projection_ratio.md",
                      fastest.markdown() + "\nThe book's fastest against the fastest peer (ratio of the medians):\n\n" +
                          ratios + "\n" + measured_by_line(command));
}

}  // namespace ch10
