// The registry's methods as the book's tables (see method_tables.hpp).
#include "program/method_tables.hpp"

#include "analysis/tableau_properties.hpp"
#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace cloth {

namespace {

std::string code(const std::string& name) { return "`" + name + "`"; }

// "2", or "2, embedded 3" for a pair.
std::string order_cell(const TableauProperties& p) {
  std::string cell = std::to_string(p.order);
  if (p.embedded_order > 0) cell += ", embedded " + std::to_string(p.embedded_order);
  return cell;
}

// R(infinity) is computed to about 1e-11: an integer is printed as one (0, -1), anything else to 4 digits.
std::string limit_cell(double r) {
  const double nearest = std::round(r);
  if (std::abs(r - nearest) <= 1e-9) return std::to_string(static_cast<long long>(nearest));
  return format_number(r, 4);
}

std::string stability_cell(const TableauProperties& p) {
  std::string cell = p.l_stable ? "L-stable" : p.a_stable ? "A-stable" : "";
  if (p.symplectic) cell += cell.empty() ? "symplectic" : ", symplectic";
  return cell;
}

// The registry's descriptions cite their sources as plain text, which --help prints and the listings show as it
// is; in the book's tables each citation becomes a link to its entry on the references page.
std::string linked(std::string text) {
  static const std::pair<const char*, const char*> citations[] = {
      {"Alexander 1977", "ref_alexander1977"},         {"Andersen 1983", "ref_andersen1983"},
      {"Bogacki & Shampine 1989", "ref_bogacki1989"},  {"Cash & Karp 1990", "ref_cash1990"},
      {"Crank & Nicolson 1947", "ref_crank1947"},      {"Dormand & Prince 1980", "ref_dormand1980"},
      {"Fehlberg 1969", "ref_fehlberg1969"},           {"Goldenthal et al. 2007", "ref_goldenthal2007"},
      {"Hosea & Shampine 1996", "ref_hosea1996"},      {"Kennedy & Carpenter 2016", "ref_kennedy2016"},
      {"Macklin et al. 2016", "ref_macklin2016"},      {"Macklin et al. 2019", "ref_macklin2019"},
      {"Tsitouras 2011", "ref_tsitouras2011"}};
  for (const auto& [citation, anchor] : citations) {
    const std::size_t at = text.find(citation);
    if (at != std::string::npos)
      text.replace(at, std::char_traits<char>::length(citation),
                   std::string("\\ref ") + anchor + " \"" + citation + "\"");
  }
  return text;
}

}  // namespace

MarkdownTable explicit_method_table() {
  MarkdownTable table({"name", "stages", "order", "description"}, "lrrl");
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) {
    const TableauProperties p = tableau_properties(*m->tableau);
    table.add_row({code(m->name), std::to_string(p.stages), order_cell(p), linked(m->description)});
  }
  return table;
}

MarkdownTable implicit_method_table() {
  MarkdownTable table({"name", "stages", "order", "stiffly accurate", "R(∞)", "stability", "description"}, "lrrlrll");
  for (const Method* m : newton_methods()) {
    if (!m->tableau) {  // a multistep row: no tableau to compute from
      table.add_row({code(m->name), "multistep", std::to_string(m->order), "", "", "", linked(m->description)});
      continue;
    }
    const TableauProperties p = tableau_properties(*m->tableau);
    const std::string stages = std::to_string(p.stages) + (p.explicit_first_stage ? " (explicit first)" : "");
    table.add_row({code(m->name), stages, order_cell(p), p.stiffly_accurate ? "yes" : "no", limit_cell(p.r_infinity),
                   stability_cell(p), linked(m->description)});
  }
  return table;
}

}  // namespace cloth
