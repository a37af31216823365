// Chapter 10's practitioner's question: what each method costs to reach 1 cm and 1 mm at T on the stiff fabric,
// read off the error curves (error_curves.cpp), and which run, explicit or implicit, gets there first.
#include "real_cloth.hpp"

#include "program/fragment.hpp"

#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [verdict]
// The fastest explicit and the fastest implicit run that reached each accuracy, in one sentence each.
void verdicts(const Settings& s, const Curves& c, const std::vector<std::string>& methods, const std::string& tag,
              std::string& summary) {
  for (double tol : {1e-2, 1e-3}) {
    const Measurement* best_explicit = nullptr;
    const Measurement* best_implicit = nullptr;
    for (const std::string& method : methods) {
      const Measurement* m = cheapest(c.rows, method, tol);
      if (m == nullptr) continue;
      const Measurement*& slot = is_explicit(method) ? best_explicit : best_implicit;
      if (slot == nullptr || m->seconds < slot->seconds) slot = m;
    }
    const auto run = [](const Measurement* m) {
      return format("%s at h = %s (%lld steps), %.3g s, error %.2g m", label(m->method).c_str(),
                    step_text(m->h).c_str(), m->steps, m->seconds, m->error);
    };
    const std::string accuracy = tol == 1e-2 ? "1 cm" : "1 mm";
    std::string sentence;
    if (best_explicit && best_implicit) {
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
  MarkdownTable table({"method", "1 cm: step h [s]", "steps", "CPU time [s]", "error [m]", "1 mm: step h [s]", "steps",
                       "CPU time [s]", "error [m]"},
                      "lrrrrrrrr");
  for (const std::string& method : methods) {
    std::vector<std::string> row = {label(method)};
    for (double tol : {1e-2, 1e-3}) {
      const Measurement* m = cheapest(c.rows, method, tol);
      for (const std::string& cell : m == nullptr ? std::vector<std::string>{"-", "-", "-", "-"}
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
  note += format(". At T the farthest particle is %.3g m from its rest position. A dash: no step tried reached the "
                 "accuracy.", c.displacement);
  write_text_fragment(s.out + "/practitioner_" + tag + "_note.md", note);
  write_text_fragment(s.out + "/displacement_" + tag + ".md", format("%.3g m", c.displacement));
  verdicts(s, c, methods, tag, summary);
}

}  // namespace ch10
