// How Chapter 6's page writes numbers and names: the short number formats of its tables and sentences, the
// titles of the sweep's methods and configurations, and the log-log slope its exponents are fitted with.
#pragma once

#include "sweep.hpp"

#include <string>
#include <vector>

namespace ch06 {

/// The title a reader reads for a composed method name: "implicit Euler, 1 iteration, CG" for implicit_euler/one/cg.
std::string method_title(const std::string& name);
/// (50, 0) for the configuration K50_D0.
std::string config_title(const Config& c);
/// %g with `digits` significant digits and a short exponent: 0.12, 1e-4, 9.4e6.
std::string g(double x, int digits = 2);
/// Always in exponent form, for numbers far from one: 9.0e-4 rather than 0.0009.
std::string sci(double x, int digits = 2);
/// A quantity of a hundred or more without a fractional part, below it with `digits` significant digits.
std::string whole_or(double x, int digits);
/// Seconds as milliseconds: "12 ms", "0.31 ms".
std::string ms(double seconds);
/// A timing with its spread: "12 ms (12-14)", the fastest run, then the fastest and slowest in milliseconds.
std::string ms_with_spread(double fastest, double slowest);
/// A required error: 1e-4 (m).
std::string power_of_ten(double x);
/// A step T / 2^k as the page writes it: 1/64 (s).
std::string step_text(double h);
/// The least-squares slope of log y against log x.
double log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace ch06
