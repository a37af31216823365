// Butcher tableaus: the order conditions that check them, and the tableau file format.
#include "integrators/butcher_tableau.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"
#include "base/text_file.hpp"

#include <cmath>
#include <sstream>
#include <sys/stat.h>

namespace cloth {

namespace {

// Rounding tolerance of the checks: tableaus are given as fractions, so their conditions hold to a few ulps.
constexpr double tolerance = 1e-12;

}  // namespace

double order_condition_defect(const ButcherTableau& t, int p) {
  const Eigen::VectorXd& b = t.b;
  const Eigen::VectorXd& c = t.c;
  const Eigen::VectorXd Ac = t.A * c;
  double defect = 0;
  const auto check = [&](double lhs, double rhs) { defect = std::max(defect, std::abs(lhs - rhs)); };
  // The conditions of order p are the rooted trees with p nodes (Butcher 2016, Table 312(I)).
  switch (p) {
    case 1: check(b.sum(), 1.0); break;
    case 2: check(b.dot(c), 1.0 / 2); break;
    case 3:
      check(b.dot(c.cwiseProduct(c)), 1.0 / 3);
      check(b.dot(Ac), 1.0 / 6);
      break;
    case 4:
      check(b.dot(c.array().cube().matrix()), 1.0 / 4);
      check(b.dot(c.cwiseProduct(Ac)), 1.0 / 8);
      check(b.dot(t.A * c.cwiseProduct(c)), 1.0 / 12);
      check(b.dot(t.A * Ac), 1.0 / 24);
      break;
    default: break;
  }
  return defect;
}

void validate(const ButcherTableau& t) {
  const std::string who = "tableau '" + t.name + "': ";
  const int s = static_cast<int>(t.b.size());
  if (s == 0) throw InputError(who + "has no stage");
  if (t.A.rows() != s || t.A.cols() != s || t.c.size() != s)
    throw InputError(who + "A must be " + std::to_string(s) + "x" + std::to_string(s) + " to match " +
                     std::to_string(s) + " weights b");
  if (!t.A.allFinite() || !t.b.allFinite() || !t.c.allFinite()) throw InputError(who + "has a non-finite entry");
  for (int i = 0; i < s; ++i)
    for (int j = i; j < s; ++j)
      if (t.A(i, j) != 0.0)
        throw InputError(who + "a_" + std::to_string(i + 1) + std::to_string(j + 1) + " = " + format_number(t.A(i, j), 17) +
                         " is on or above the diagonal: the method is implicit, and this engine runs explicit "
                         "methods only (A strictly lower triangular)");
  for (int i = 0; i < s; ++i) {
    const double row_sum = t.A.row(i).sum();
    if (std::abs(t.c[i] - row_sum) > tolerance)
      throw InputError(who + "row " + std::to_string(i + 1) + ": c_" + std::to_string(i + 1) + " = " + format_number(t.c[i], 17) +
                       " but the row sum of A is " + format_number(row_sum, 17) + " (consistency needs c_i = sum_j a_ij)");
  }
  if (t.order < 1 || t.order > 4)
    throw InputError(who + "claims order " + std::to_string(t.order) + ": expected an order from 1 to 4 (the "
                     "conditions this program checks)");
  // The order conditions, by order, as the error message states them.
  static const char* const conditions[] = {
      "",
      "sum b_i = 1",
      "sum b_i c_i = 1/2",
      "sum b_i c_i^2 = 1/3 and sum b_i a_ij c_j = 1/6",
      "sum b_i c_i^3 = 1/4, sum b_i c_i a_ij c_j = 1/8, sum b_i a_ij c_j^2 = 1/12, sum b_i a_ij a_jk c_k = 1/24"};
  for (int p = 1; p <= t.order; ++p) {
    const double defect = order_condition_defect(t, p);
    if (defect > tolerance)
      throw InputError(who + "claims order " + std::to_string(t.order) + " but the order-" + std::to_string(p) +
                       " condition " + conditions[p] + " fails by " + format_number(defect, 17));
  }
  // A claim below what the conditions give would label the method's results (the observed order of Chapter 3,
  // the tables of Chapter 6) with the wrong order.
  int satisfied = t.order;
  while (satisfied < 4 && order_condition_defect(t, satisfied + 1) <= tolerance) ++satisfied;
  if (satisfied > t.order)
    throw InputError(who + "claims order " + std::to_string(t.order) + " but satisfies the order conditions through "
                     "order " + std::to_string(satisfied) + ": expected 'order " + std::to_string(satisfied) + "'");
}

// A number as a decimal or a fraction p/q, so that tableaus can be written as exactly as they are printed.
bool parse_tableau_entry(const std::string& token, double& value) {
  const auto slash = token.find('/');
  const auto number = [](const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(out);
  };
  if (slash == std::string::npos) return number(token, value);
  double p = 0, q = 0;
  if (!number(token.substr(0, slash), p) || !number(token.substr(slash + 1), q) || q == 0) return false;
  value = p / q;
  return true;
}

ButcherTableau parse_tableau_entries(const std::string& text, const std::string& source_name) {
  const std::string source = escaped(source_name);
  ButcherTableau t;
  t.name = source;
  t.order = 0;
  int name_line = 0, order_line = 0;  // where 'name' and 'order' were given, to refuse a second one
  std::vector<std::vector<double>> rows;
  std::vector<int> row_lines;
  std::vector<double> b;
  bool have_b = false;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  const auto fail = [&](const std::string& what) {
    throw InputError(source + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (first == "name") {
      if (name_line != 0) fail("'name' given twice (first on line " + std::to_string(name_line) + "): expected one");
      name_line = line_no;
      if (!(words >> t.name)) fail("'name' needs a value");
    } else if (first == "order") {
      if (order_line != 0) fail("'order' given twice (first on line " + std::to_string(order_line) + "): expected one");
      order_line = line_no;
      std::string o;
      if (!(words >> o) || o.size() != 1 || o[0] < '1' || o[0] > '4') fail("'order' needs a whole number from 1 to 4");
      t.order = o[0] - '0';
    } else {
      if (have_b) fail("nothing may follow the 'b' row");
      std::vector<double> values;
      std::string token;
      std::istringstream entries(first == "b" ? line.substr(line.find('b') + 1) : line);
      while (entries >> token) {
        double value = 0;
        if (!parse_tableau_entry(token, value)) fail("'" + token + "' is not a number (write decimals or fractions p/q)");
        values.push_back(value);
      }
      if (first == "b") {
        b = values;
        have_b = true;
      } else {
        rows.push_back(values);
        row_lines.push_back(line_no);
      }
    }
  }
  if (rows.empty() && !have_b)
    throw InputError(source + ": empty tableau: expected rows 'c_i a_i1 ... a_is' and a row 'b b_1 ... b_s'");
  if (!have_b) throw InputError(source + ": no 'b' row: expected a last row 'b b_1 ... b_s'");
  if (t.order == 0) throw InputError(source + ": no 'order' line: expected 'order p' with p from 1 to 4");
  const int s = static_cast<int>(b.size());
  if (s == 0) throw InputError(source + ": the 'b' row has no weight");
  if (static_cast<int>(rows.size()) != s)
    throw InputError(source + ": " + std::to_string(rows.size()) + " stage rows but " + std::to_string(s) +
                     " weights in b: expected one row 'c_i a_i1 ... a_is' per weight");
  t.A.resize(s, s);
  t.c.resize(s);
  for (int i = 0; i < s; ++i) {
    if (static_cast<int>(rows[static_cast<std::size_t>(i)].size()) != s + 1) {
      line_no = row_lines[static_cast<std::size_t>(i)];
      fail("stage row " + std::to_string(i + 1) + " has " + std::to_string(rows[static_cast<std::size_t>(i)].size()) +
           " numbers: expected " + std::to_string(s + 1) + " (c_i, then " + std::to_string(s) + " entries of A)");
    }
    t.c[i] = rows[static_cast<std::size_t>(i)][0];
    for (int j = 0; j < s; ++j) t.A(i, j) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j + 1)];
  }
  t.b = Eigen::Map<const Eigen::VectorXd>(b.data(), s);
  return t;
}

ButcherTableau parse_tableau(const std::string& text, const std::string& source_name) {
  ButcherTableau t = parse_tableau_entries(text, source_name);
  try {
    validate(t);
  } catch (const InputError& e) {
    throw InputError(escaped(source_name) + ": " + e.what());
  }
  return t;
}

std::string read_tableau_text(const std::string& path) {
  // A tableau is a few lines; 64 KiB leaves room for comments and stops a wrong path from being read for long.
  return read_text_file(path, 64 * 1024);
}

ButcherTableau read_tableau(const std::string& path) { return parse_tableau(read_tableau_text(path), path); }

}  // namespace cloth
