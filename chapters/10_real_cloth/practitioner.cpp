// Chapter 10's practitioner's question: what each method costs to reach 1 cm and 1 mm at T on the stiff fabric,
// read off the error curves (error_curves.cpp), and which run, explicit or implicit, gets there first. A level the
// rest state already meets (the four-corner sheet moves 6.7 mm by T = 0.5 s) is said so and is nobody's win.
#include "real_cloth.hpp"

#include "analysis/trajectory_measures.hpp"

#include "program/fragment.hpp"

#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [verdict]
// The fastest explicit and the fastest implicit run that reached each accuracy, in one sentence each; none at a
// level the rest state meets (cheapest() finds no run there), which the sentence says instead.
void verdicts(const Settings& s, const Curves& c, const std::vector<std::string>& methods, const std::string& tag,
              std::string& summary) {
  for (double tol : {1e-2, 1e-3}) {
    const Measurement* best_explicit = nullptr;
    const Measurement* best_implicit = nullptr;
    for (const std::string& method : methods) {
      const Measurement* m = cheapest(c, method, tol);
      if (m == nullptr) continue;
      const Measurement*& slot = is_explicit(method) ? best_explicit : best_implicit;
      if (slot == nullptr || m->seconds < slot->seconds) slot = m;
    }
    const auto run = [](const Measurement* m) {
      return format("%s at h = %s (%lld steps), %.3g s, error %.2g m", label(m->method).c_str(),
                    step_text(m->h).c_str(), m->steps, m->seconds, m->error);
    };
    const std::string accuracy = format("%s (the motion at T is %.3g m)", tol == 1e-2 ? "1 cm" : "1 mm",
                                        c.displacement);
    std::string sentence;
    if (accuracy_verdict(0, c.displacement, tol) == AccuracyVerdict::met_by_rest) {
      sentence = format("%s is %s: no run is counted as reaching it.", tol == 1e-2 ? "1 cm" : "1 mm",
                        met_by_standing_still(c.displacement).c_str());
    } else if (best_explicit && best_implicit) {
      const bool implicit_wins = best_implicit->seconds < best_explicit->seconds;
      const Measurement* winner = implicit_wins ? best_implicit : best_explicit;
      const Measurement* other = implicit_wins ? best_explicit : best_implicit;
      sentence = format("To %s the fastest run is %s; the fastest %s one is %s, %.1f times as long.", accuracy.c_str(),
                        run(winner).c_str(), implicit_wins ? "explicit" : "implicit", run(other).c_str(),
                        other->seconds / winner->seconds);
    } else if (best_explicit || best_implicit) {
      sentence = format("To %s the fastest run is %s; no %s run tried got there.", accuracy.c_str(),
                        run(best_explicit ? best_explicit : best_implicit).c_str(),
                        best_explicit ? "implicit" : "explicit");
    } else {
      sentence = "No run tried got to " + accuracy + ".";
    }
    summary += format("T = %g s: %s\n", c.T, sentence.c_str());
    write_text_fragment(s.out + format("/verdict_%s_%s.md", tag.c_str(), tol == 1e-2 ? "1cm" : "1mm"), sentence);
  }
}
// [verdict]

}  // namespace

void practitioner(const Settings& s, const Curves& c, const std::vector<std::string>& methods, std::string& summary) {
  const std::string tag = format("T%g", c.T);
  write_curves(s, c, "practitioner_" + tag);
  const auto level = [&](const char* name) { return format("%s (motion %.3g m): step h [s]", name, c.displacement); };
  MarkdownTable table({"method", level("1 cm"), "steps", "CPU time [s]", "error [m]", level("1 mm"), "steps",
                       "CPU time [s]", "error [m]"},
                      "lrrrrrrrr");
  for (const std::string& method : methods) {
    std::vector<std::string> row = {label(method)};
    for (double tol : {1e-2, 1e-3}) {
      const Measurement* m = cheapest(c, method, tol);
      const bool still = accuracy_verdict(0, c.displacement, tol) == AccuracyVerdict::met_by_rest;
      for (const std::string& cell : still        ? std::vector<std::string>{"met by standing still", "", "", ""}
                                     : m == nullptr ? std::vector<std::string>{"-", "-", "-", "-"}
                                                  : std::vector<std::string>{step_text(m->h), format("%lld", m->steps),
                                                                             format("%.3g", m->seconds),
                                                                             format("%.2g", m->error)})
        row.push_back(cell);
    }
    table.add_row(row);
  }
  write_table_fragment(s.out + "/practitioner_" + tag + ".md", table, s.command);
  std::string note = format("Reference: RK4 with %lld steps", c.reference_steps);
  if (c.reference_agreement >= 0)
    note += format("; the 3/8 rule with twice as many steps agrees with it to %.1e m", c.reference_agreement);
  note += format(". The size of the motion: at T the farthest particle is %.3g m from its rest position, so the "
                 "rest state is that far from the reference and a level at least as large is met by standing still, "
                 "no run's win. A dash: no step tried reached the accuracy.",
                 c.displacement);
  write_text_fragment(s.out + "/practitioner_" + tag + "_note.md", note);
  write_text_fragment(s.out + "/displacement_" + tag + ".md", format("%.3g m", c.displacement));
  verdicts(s, c, methods, tag, summary);
}

}  // namespace ch10
