// The incline case study of seed 000: table 1 reproduced with eq 十A, the printed slopes and
// accelerations re-computed, the setups of figures 二-八 evaluated, and the errata found.
// Pure data, no printing: the `demo` command formats it.
#pragma once

#include "incline/closed_form.hpp"
#include "incline/params.hpp"
#include "numerics/units.hpp"

#include <string>
#include <vector>

namespace tribolab::incline {

/// One column of the seed's table 1 (表一): mu from the stopping point vs mu_o = 0.634.
struct Table1Row {
  double phi_deg = 0;          ///< incline angle, degrees
  double x_stop = 0;           ///< m (printed x_f)
  double y_stop = 0;           ///< m (printed |y_f| with the sign of our frame: < 0)
  double mu_printed = 0;       ///< the seed's mu_A
  double mu = 0;               ///< ours (eq 十A solved by bracketing)
  double diff_percent_printed = 0;  ///< the seed's (mu_A - mu_o)/mu_o, %
  double diff_percent = 0;     ///< ours, %
};

/// A number printed in the seed compared with our independent computation.
struct PrintedCheck {
  std::string where;      ///< figure / equation in the seed, e.g. "圖八-2 slope t_f/v_x0"
  double printed = 0;
  double computed = 0;
  double tolerance = 0;   ///< half a unit of the last printed digit (absolute)
  bool agrees = false;    ///< |printed - computed| <= tolerance
  std::string note;       ///< how we computed it
};

/// A setup of the seed's figures evaluated with the closed form.
struct SetupResult {
  std::string figure;     ///< e.g. "圖五 (v0 family), v0 = 2.62 m/s"
  Parameters parameters;
  Prediction prediction;
};

struct CaseStudy {
  double mu_o = 0.634;            ///< the seed's reference mu (eq a)
  double mu_o_from_eq_a = 0;      ///< ours from phi = 41.09 deg, a = 1.758 m/s^2
  std::vector<Table1Row> table1;
  std::vector<PrintedCheck> checks;
  std::vector<SetupResult> setups;
  std::vector<std::string> errata;  ///< one line each, also in docs/theory.md
};

/// mu from a straight slide down the incline (seed eq a): (g sin phi - a) / (g cos phi).
double mu_from_slide_acceleration(double phi, double a, double g = kDefaultG);

/// Computes the whole case study (a few milliseconds).
CaseStudy seed000_case_study();

}  // namespace tribolab::incline
