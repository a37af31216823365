// Chapter 10's studies of real cloth in physical units, one file each, run by main.cpp in the order of the page:
// the fabric preset (preset.cpp), the same square metre at finer grids (refinement.cpp), the explicit stable step
// (stable_step.cpp), every method's error against its cost (error_curves.cpp), the practitioner's question
// (practitioner.cpp) and the map of the cheapest method (cost_map.cpp).
#pragma once

#include "program/output_spec.hpp"
#include "study.hpp"

#include <map>
#include <string>
#include <vector>

namespace ch10 {

/// What every study of the program needs: the reduced sweep or the full one, and where its files go.
struct Settings {
  bool quick = false;
  std::string out;
  std::string command;  ///< what a reader types to measure the tables again (cloth::reader_command)
};

/// The fabric preset at 20 to 153 particles per side (preset.md).
void preset(const Settings& s);

/// The same square metre with 20, 39 (and 77, 153) particles per side (refinement.md, refinement.dat,
/// fabric_frames.dat).
void refinement(const Settings& s);

/// Stability interval on the imaginary axis: symplectic Euler 2, RK4 2 sqrt 2.
double stability_reach(const std::string& method);

/// The explicit methods' stable step, predicted from the lattice and measured, at each stiffness (stable_step.md,
/// stable_step_agreement.md, stable_step.dat).
void stable_steps(const Settings& s, const std::vector<double>& stiffnesses);

// [methods]
/// The stiffnesses of the sweep [N/m] and its methods, by their one names.
inline const std::vector<double> stiffnesses = {1e3, 1e4, 1e5, 1e6};
inline const std::vector<std::string> methods = {"symplectic_euler",      "rk4",
                                                 "implicit_euler/exact",  "implicit_euler/one/exact",
                                                 "implicit_euler/one/cg", "implicit_euler/cg",
                                                 "local_global",          "local_global/50it"};
// [methods]

/// One run of a sweep: a method at one step, its cost and its error at T.
struct Measurement {
  std::string method;
  double h = 0;
  long long steps = 0;
  double seconds = 0, error = 0;
  bool ok = true;
  std::string message;
  cloth::StepCounters counters;
};

/// Every method's runs on the 20 x 20 fabric of stiffness K, to T, against a reference.
struct Curves {
  double K = 0, T = 0;
  long long reference_steps = 0;
  double reference_agreement = -1;  ///< RK4 against the 3/8 rule, when checked
  double displacement = 0;          ///< the size of the motion at T: the rest state's distance from the reference
  std::vector<Measurement> rows;
};

/// How the sweep of error_curves runs: its budget per run, its halvings, and the reference's fraction of RK4's
/// stable step.
struct CurvePlan {
  double budget = 2.0;        ///< no more halvings once a run costs more CPU seconds than this
  int max_halvings = 7;
  double reference_division = 4;
};

/// Every method at its candidate steps, halving each until 0.5 mm at T or the plan's limits.
Curves error_curves(double K, double T, const std::vector<std::string>& methods, bool check_reference,
                    const CurvePlan& plan);
/// Prints one sweep's reference and every run of it, as the progress of the program.
void print_curves(const Curves& c);
/// The tag of the sweep's file at stiffness K: curves_K1000.dat (printf's %g).
std::string curves_tag(double K);
/// Writes the sweep as curves_TAG.dat, one gnuplot block per method.
void write_curves(const Settings& s, const Curves& c, const std::string& tag);
/// The cheapest run of `method` whose error at T is at most tol (nullptr when none, and at every tol the rest
/// state meets: tol >= c.displacement, where standing still is no win; cloth::fastest_reaching).
const Measurement* cheapest(const Curves& c, const std::string& method, double tol);

/// The practitioner's question at c.T: each method's cheapest run to 1 cm and 1 mm, and the verdicts
/// (practitioner_TAG.md and its note, displacement_TAG.md, verdict_TAG_1cm.md, verdict_TAG_1mm.md); the verdicts'
/// sentences are appended to `summary`.
void practitioner(const Settings& s, const Curves& c, const std::vector<std::string>& methods, std::string& summary);

/// The map of the cheapest method over the grid and K, from the measured cost of a step (step_cost.md, map_1cm.md,
/// map_1mm.md and their data).
void cost_map(const Settings& s, const std::map<double, Curves>& curves, const std::vector<std::string>& methods);

/// Every file the program writes without `--curtain`: `quick`, the reduced sweep's; else the full sweep's.
cloth::OutputList real_cloth_outputs(bool quick);

}  // namespace ch10
