// The observed orders: each method's error at T against the step on the report's damped cloth, and the order
// log(e(2h) / e(h)) / log 2 it shows between the two smallest steps.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"

#include <cmath>

using namespace cloth;

namespace ch09 {

void orders_study(const Study& study) {
  const SceneParams report = report_cloth(study.opt.scene);
  const std::vector<double> hs = study_steps(study.quick);
  WorkPrecision spec{report, study_horizon, hs, {}, study.newton, {NewtonVariant::modified}, 1, {}};
  spec.newton.tolerance = 1e-12;  // Newton's error far below the truncation error: the orders are the methods'
  // The stage equations as they are: dampers frozen for the step change each stage by O(h^3), which would hide
  // every order above 2.
  spec.newton.line_search = LineSearch::residual;
  // RK4 at h = 2e-5: its error (order 4) is below 1e-9 m here, far below every implicit method's.
  spec.reference = reference_positions(report, study_horizon, 2e-5);
  const std::vector<StudyRun> orders = work_precision(spec, study.dir + "/orders.dat");
  // The observed order between consecutive steps, log2(e(2h) / e(h)), for each method (runs come h-descending).
  std::vector<std::string> header = {"(K, D) = (200, 20), T = 0.4 s"};
  for (const double h : hs) header.push_back(std::string("error at h = ") + format_number(h) + " [m]");
  header.emplace_back("observed order");
  std::string alignment(header.size(), 'r');  // the method's name left, the numbers right
  alignment[0] = 'l';
  MarkdownTable order_table(header, alignment);
  for (std::size_t k = 0; k + hs.size() <= orders.size(); k += hs.size()) {
    std::vector<std::string> row = {orders[k].title};
    for (std::size_t j = 0; j < hs.size(); ++j) row.push_back(format_number(orders[k + j].error, 2));
    const StudyRun& coarse = orders[k + hs.size() - 2];
    const StudyRun& fine = orders[k + hs.size() - 1];
    row.push_back(format_fixed(std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h), 2));
    order_table.add_row(row);
  }
  write_table_fragment(study.dir + "/orders.md", order_table, study.command);
}

}  // namespace ch09
