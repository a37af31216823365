// How Chapter 6's page writes numbers and names (see page_text.hpp). Nothing here measures anything.
#include "page_text.hpp"

#include "base/format_number.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace ch06 {

using namespace cloth;

std::string method_title(const std::string& name) {
  static const std::map<std::string, std::string> titles = {
      {"explicit_euler", "explicit Euler"},
      {"symplectic_euler", "symplectic Euler"},
      {"heun", "Heun"},
      {"rk4", "RK4"},
      {"rule38", "3/8 rule"},
      {"implicit_euler", "implicit Euler, Newton, direct"},
      {"implicit_euler/cg", "implicit Euler, Newton, CG"},
      {"implicit_euler/one", "implicit Euler, 1 iteration, direct"},
      {"implicit_euler/one/cg", "implicit Euler, 1 iteration, CG"},
      {"dopri5", "adaptive Dormand-Prince"}};
  const auto it = titles.find(name);
  return it == titles.end() ? name : it->second;
}

std::string config_title(const Config& c) {
  std::string title = "(";  // built by appending: GCC 12 warns falsely about "literal" + a temporary string
  return title.append(format_number(c.K)).append(", ").append(format_number(c.D)).append(")");
}

namespace {

// "9.4e+06" as 9.4e6, "1e-04" as 1e-4.
std::string short_exponent(const std::string& text) {
  const auto e = text.find('e');
  if (e == std::string::npos) return text;
  const bool negative = text[e + 1] == '-';
  return text.substr(0, e + 1) + (negative ? "-" : "") + text.substr(text.find_first_not_of("+-0", e + 1));
}

}  // namespace

std::string g(double x, int digits) { return short_exponent(format_number(x, digits)); }

std::string sci(double x, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, x);
  return short_exponent(buffer);
}

std::string whole_or(double x, int digits) { return x >= 100 ? std::to_string(std::llround(x)) : g(x, digits); }

std::string ms(double seconds) { return whole_or(1e3 * seconds, 2) + " ms"; }

std::string ms_with_spread(double fastest, double slowest) {
  return ms(fastest) + " (" + whole_or(1e3 * fastest, 2) + "-" + whole_or(1e3 * slowest, 2) + ")";
}

std::string power_of_ten(double x) { return "1e" + std::to_string(std::lround(std::log10(x))); }

std::string step_text(double h) { return "1/" + std::to_string(std::llround(1 / h)); }

double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace ch06
