// Report pages of the incline commands (`incline simulate`, `families`, `predict`) and the
// building blocks the demo's incline case study shares with them: the seven kinematics
// figures of a set of launches and the model-B equations with the seed's numbers.
#pragma once

#include "incline/closed_form.hpp"
#include "incline/families.hpp"
#include "incline/params.hpp"
#include "report/report.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

/// One launch drawn in the kinematics figures.
struct InclineCurve {
  std::string name;                    ///< legend entry, e.g. "v0 = 2.62 m/s"
  std::vector<incline::State> states;  ///< samples in time order
  report::Mode mode = report::Mode::Lines;
  report::Dash dash = report::Dash::Solid;
  std::string color;                   ///< empty = Plotly's cycle
};

/// A curve drawn with lines; `dash` and `color` as in report::Series.
inline InclineCurve incline_curve(std::string name, std::vector<incline::State> states,
                                  report::Dash dash = report::Dash::Solid, std::string color = {}) {
  return {std::move(name), std::move(states), report::Mode::Lines, dash, std::move(color)};
}

/// Adds the seven figures x–t, y–t, trajectory y–x, vx–t, vy–t, ax–t, ay–t of `curves` to `s`,
/// titled "<title>: x–t" etc. Returns the number of figures added (7).
int add_incline_kinematics(report::Section& s, const std::string& title,
                           const std::vector<InclineCurve>& curves, const std::string& caption = {});

/// The model-B equations (seed 000, eqs 1.1, 1.2, 二, 三, 五, 六, 七, 八, 九) as report::Equation.
void add_model_b_equations(report::Section& s);

/// A two-column table of the launch parameters (mu, phi, v0, g, k, regime).
report::Table incline_parameter_table(const incline::Parameters& p);

/// The sample times a simulate report draws: at most 2001 evenly chosen among `states`
/// (first and last kept), so the report stays small for any --dt.
std::vector<double> incline_report_times(const std::vector<incline::State>& states);

/// `incline simulate --report`: the trajectory sampled as the CSV (thinned to
/// incline_report_times), and for model B the other method as the workflow computed it on
/// those times (`comparison`, named `comparison_name`; empty = not drawn) with the difference.
report::Report incline_simulate_report(const incline::Parameters& p, bool model_a,
                                       const std::string& method,
                                       const std::vector<incline::State>& states,
                                       const std::vector<incline::State>& comparison = {},
                                       const std::string& comparison_name = {});

/// `incline families --report`: the family's curves (seed figures 五–七) and stop table.
report::Report incline_families_report(const incline::FamilyOptions& options,
                                       const incline::Family& family);

/// `incline predict --report`: the key numbers and `trajectory` as the workflow computed it
/// (to 1.25 t_stop, or over 2 v0/alpha; empty = not drawn: no finite duration).
report::Report incline_predict_report(const incline::Parameters& p, const incline::Prediction& pr,
                                      const std::vector<incline::State>& trajectory);

}  // namespace tribolab::app
