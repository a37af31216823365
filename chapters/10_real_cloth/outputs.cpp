// The files ch10_real_cloth writes without --curtain, each declared once (program/output_spec.hpp): what the page
// includes (fragments), what plot.gp draws, and the data kept for the reader.
#include "real_cloth.hpp"

#include "program/output_kinds.hpp"

using namespace cloth;

namespace ch10 {

namespace {

// The practitioner's table at T (tag "T0.5"): fragments of the page at T = 0.5 s, else data for the reader.
OutputList practitioner_outputs(const std::string& tag, bool on_the_page) {
  const OutputKind table = on_the_page ? OutputKind::fragment : OutputKind::data;
  const std::string at = format(" at %s s", tag.substr(1).c_str());
  return {{"practitioner_" + tag + ".md", table, "each method's cheapest run to 1 cm and to 1 mm" + at},
          {"practitioner_" + tag + "_note.md", table, "the reference and the motion" + at},
          {"displacement_" + tag + ".md", table, "the farthest particle's distance from rest" + at},
          {"verdict_" + tag + "_1cm.md", table, "the fastest explicit and implicit run to 1 cm" + at},
          {"verdict_" + tag + "_1mm.md", table, "the fastest explicit and implicit run to 1 mm" + at},
          {"curves_practitioner_" + tag + ".dat", on_the_page ? OutputKind::figure_input : OutputKind::data,
           "every run of the sweep" + at + ": step, CPU time, error, work counters"}};
}

}  // namespace

OutputList real_cloth_outputs(bool quick) {
  using namespace cloth::output_kinds;
  OutputList files = {
      {"preset.md", fragment, "the fabric preset at 20 to 153 particles per side"},
      {"stable_step.md", fragment, "the explicit methods' stable step, predicted and measured"},
      {"stable_step_agreement.md", fragment, "how well the prediction holds"},
      {"stable_step.dat", data, "the stable steps and frequencies of stable_step.md"},
      {"practitioner_summary.txt", data, "the verdicts' sentences, one per T and accuracy"},
      {"refinement.md", fragment, "each grid's largest distance to the next finer grid's"},
      {"refinement.dat", data, "the distances of refinement.md"},
      {"fabric_frames.dat", figure, "the 39 x 39 fabric at t = 0, 0.1, ..., 0.5 s"},
      {"step_cost.md", fragment, "each method's CPU time per step against the grid"},
      {"step_cost.dat", data, "the costs of step_cost.md"},
      {"map_1cm.md", fragment, "the predicted cheapest method to 1 cm at each grid and K"},
      {"map_1mm.md", fragment, "the predicted cheapest method to 1 mm at each grid and K"},
      {"map.dat", data, "every method's predicted CPU time at each accuracy, K and grid"},
      {"map_winners.dat", figure, "the cheapest method at each accuracy, K and grid"}};
  for (double K : stiffnesses)
    files.push_back({format("curves_%s.dat", curves_tag(K).c_str()), data,
                     format("every run of the sweep at K = %s N/m: step, CPU time, error, counters",
                            stiffness_text(K).c_str())});
  files = files + practitioner_outputs("T0.5", true);
  if (!quick) files = files + practitioner_outputs("T1", false);  // the full sweep's question over a whole second
  return files;
}

}  // namespace ch10
