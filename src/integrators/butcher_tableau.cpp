// Butcher tableaus: the order conditions that check them (generated from the rooted trees, for b and for an
// embedded pair's b-hat), and the tableau file format.
#include "integrators/butcher_tableau.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/parse_number.hpp"
#include "base/text.hpp"
#include "base/text_file.hpp"
#include "integrators/order_conditions.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>

namespace cloth {

namespace {

// Rounding tolerance of the checks: tableaus are given as fractions, so their conditions hold to a few ulps.
constexpr double tolerance = 1e-12;

}  // namespace

bool ButcherTableau::first_same_as_last() const {
  const int s = stages();
  return s >= 2 && b[s - 1] == 0.0 && A.row(s - 1).transpose() == b;
}

double order_condition_defect(const ButcherTableau& t, int p, bool embedded) {
  return order_condition_defect(t.A, embedded ? t.b_hat : t.b, p);
}

namespace {

// The conditions of orders 1..order for one weight row, each stated as its sum when it fails.
void check_order(const ButcherTableau& t, const std::string& who, const Eigen::VectorXd& w, int order,
                 const std::string& row) {
  if (order < 1 || order > max_tree_order)
    throw InputError(who + "claims order " + std::to_string(order) + " for " + row + ": expected an order from 1 to " +
                     std::to_string(max_tree_order) + " (the conditions this program generates)");
  for (int p = 1; p <= order; ++p) {
    int worst = -1;
    const double defect = order_condition_defect(t.A, w, p, &worst);
    if (defect > tolerance) {
      const RootedTree& tree = rooted_trees()[static_cast<std::size_t>(worst)];
      std::string condition = tree.condition;
      if (row != "b") condition.replace(condition.find("b_i"), 3, "bhat_i");
      std::string message = who + "claims order " + std::to_string(order);
      if (row != "b") message += " for " + row;
      message += " but the order-" + std::to_string(p) + " condition " + condition;
      message += " (tree " + tree.bracket + ") fails by " + format_number(defect, 17);
      throw InputError(message);
    }
  }
  // A claim below what the conditions give would label the method's results (the observed order of Chapter 3,
  // the tables of Chapter 6, the step control of Chapter 8) with the wrong order.
  int satisfied = order;
  while (satisfied < max_tree_order && order_condition_defect(t.A, w, satisfied + 1) <= tolerance) ++satisfied;
  if (satisfied > order) {
    const std::string key = row == "b" ? "order" : "embedded_order";
    std::string message = who + "claims order " + std::to_string(order);
    if (row != "b") message += " for " + row;
    message += " but satisfies the order conditions through order " + std::to_string(satisfied);
    message += ": expected '" + key + " " + std::to_string(satisfied) + "'";
    throw InputError(message);
  }
}

}  // namespace

void validate(const ButcherTableau& t) {
  const std::string who = "tableau '" + t.name + "': ";
  const int s = static_cast<int>(t.b.size());
  if (s == 0) throw InputError(who + "has no stage");
  if (t.A.rows() != s || t.A.cols() != s || t.c.size() != s)
    throw InputError(who + "A must be " + std::to_string(s) + "x" + std::to_string(s) + " to match " +
                     std::to_string(s) + " weights b");
  if (t.has_embedded() && t.b_hat.size() != s)
    throw InputError(who + "bhat has " + std::to_string(t.b_hat.size()) + " weights: expected " + std::to_string(s) +
                     ", one per stage as in b");
  if (!t.A.allFinite() || !t.b.allFinite() || !t.c.allFinite() || !t.b_hat.allFinite())
    throw InputError(who + "has a non-finite entry");
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
  check_order(t, who, t.b, t.order, "b");
  if (t.has_embedded()) {
    check_order(t, who, t.b_hat, t.embedded_order, "bhat");
    if (t.b_hat == t.b) throw InputError(who + "bhat equals b: the pair would estimate every error as zero");
  }
}

// A number as a decimal or a fraction p/q, so that tableaus can be written as exactly as they are printed; each
// number, and the fraction's value, by the rule of every number the book reads (base/parse_number.hpp).
double parse_tableau_entry(const std::string& token) {
  const auto refuse = [&token](const std::string& why) {
    throw InputError("'" + escaped(token) + "' is not a number the book reads (" + why +
                     "): write decimal or hexadecimal numbers, or fractions p/q of them");
  };
  const auto number = [&refuse](const std::string& text) {
    try {
      return parse_number(text);
    } catch (const InputError& e) {
      refuse(e.what());
    }
    return 0.0;
  };
  const auto slash = token.find('/');
  if (slash == std::string::npos) return number(token);
  const double p = number(token.substr(0, slash)), q = number(token.substr(slash + 1));
  if (q == 0) refuse("a fraction with denominator 0");
  const double value = p / q;
  if (!std::isfinite(value) || (value != 0 && std::abs(value) < DBL_MIN) || (value == 0 && p != 0))
    refuse("the fraction's value is outside the normal range of a double");
  return value + 0.0;
}

ButcherTableau parse_tableau_entries(const std::string& text, const std::string& source_name) {
  const std::string source = escaped(source_name);
  ButcherTableau t;
  t.name = source;
  t.order = 0;
  std::vector<std::vector<double>> rows;
  std::vector<int> row_lines;
  std::vector<double> b, b_hat;
  bool have_b = false, have_b_hat = false;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  const auto fail = [&](const std::string& what) {
    throw InputError(source + ":" + std::to_string(line_no) + ": " + what);
  };
  int name_line = 0, order_line = 0, embedded_order_line = 0;  // where each key was given, to refuse a second one
  const auto once = [&](int& first_line, const std::string& key) {
    if (first_line != 0)
      fail("'" + key + "' given twice (first on line " + std::to_string(first_line) + "): expected one");
    first_line = line_no;
  };
  const auto order_value = [&](std::istringstream& words, const std::string& key) {
    std::string o;
    if (!(words >> o) || o.size() != 1 || o[0] < '1' || o[0] > '0' + max_tree_order)
      fail("'" + key + "' needs a whole number from 1 to " + std::to_string(max_tree_order));
    return o[0] - '0';
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (first == "name") {
      once(name_line, "name");
      if (!(words >> t.name)) fail("'name' needs a value");
    } else if (first == "order") {
      once(order_line, "order");
      t.order = order_value(words, "order");
    } else if (first == "embedded_order") {
      once(embedded_order_line, "embedded_order");
      t.embedded_order = order_value(words, "embedded_order");
    } else {
      const bool weights = first == "b" || first == "bhat";
      if ((have_b || have_b_hat) && !weights) fail("nothing but the weight rows 'b' and 'bhat' may follow the 'b' row");
      if ((first == "b" && have_b) || (first == "bhat" && have_b_hat)) fail("a second '" + first + "' row");
      std::vector<double> values;
      std::string token;
      std::istringstream entries(weights ? line.substr(line.find(first) + first.size()) : line);
      while (entries >> token) {
        try {
          values.push_back(parse_tableau_entry(token));
        } catch (const InputError& e) {
          fail(e.what());
        }
      }
      if (first == "b") {
        b = values;
        have_b = true;
      } else if (first == "bhat") {
        b_hat = values;
        have_b_hat = true;
      } else {
        rows.push_back(values);
        row_lines.push_back(line_no);
      }
    }
  }
  if (rows.empty() && !have_b)
    throw InputError(source + ": empty tableau: expected rows 'c_i a_i1 ... a_is' and a row 'b b_1 ... b_s'");
  if (!have_b) throw InputError(source + ": no 'b' row: expected a last row 'b b_1 ... b_s'");
  if (t.order == 0)
    throw InputError(source + ": no 'order' line: expected 'order p' with p from 1 to " + std::to_string(max_tree_order));
  if (have_b_hat != (t.embedded_order != 0))
    throw InputError(source + (have_b_hat ? ": a 'bhat' row needs an 'embedded_order q' line (the order of bhat)"
                                          : ": an 'embedded_order' line needs a 'bhat' row"));
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
  if (have_b_hat) t.b_hat = Eigen::Map<const Eigen::VectorXd>(b_hat.data(), static_cast<Eigen::Index>(b_hat.size()));
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
