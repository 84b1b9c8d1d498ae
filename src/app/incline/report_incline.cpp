#include "app/incline/report_incline.hpp"

#include "numerics/units.hpp"
#include "report/format.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace tribolab::app {
namespace {

using report::Figure;
using report::Series;
using report::Table;
using incline::State;

std::string deg(double rad) { return report::format_value(to_deg(rad), 4); }

Series series_of(const InclineCurve& c, const std::function<double(const State&)>& fx,
                 const std::function<double(const State&)>& fy) {
  Series s;
  s.name = c.name;
  s.mode = c.mode;
  s.dash = c.dash;
  s.color = c.color;
  s.x.reserve(c.states.size());
  s.y.reserve(c.states.size());
  for (const State& st : c.states) {
    s.x.push_back(fx(st));
    s.y.push_back(fy(st));
  }
  return s;
}

std::string optional_number(const std::optional<double>& v, const std::string& unit) {
  return v ? report::format_value(*v, 5) + unit : "—";
}

/// At most `n` + 1 evenly chosen samples (first and last kept): a report stays a few MB
/// even for a 10^7-row CSV.
std::vector<State> thin(const std::vector<State>& states, std::size_t n = 2000) {
  if (states.size() <= n + 1) return states;
  std::vector<State> out;
  out.reserve(n + 1);
  for (std::size_t i = 0; i <= n; ++i) out.push_back(states[i * (states.size() - 1) / n]);
  return out;
}

}  // namespace

std::vector<double> incline_report_times(const std::vector<incline::State>& states) {
  std::vector<double> times;
  for (const State& st : thin(states)) times.push_back(st.t);
  return times;
}

int add_incline_kinematics(report::Section& s, const std::string& title,
                           const std::vector<InclineCurve>& curves, const std::string& caption) {
  struct Panel {
    const char* suffix;
    const char* x_title;
    const char* y_title;
    std::function<double(const State&)> fx, fy;
  };
  const auto t = [](const State& st) { return st.t; };
  const Panel panels[] = {
      {"x–t", "t (s)", "x (m), across the slope", t, [](const State& st) { return st.x; }},
      {"y–t", "t (s)", "y (m), up the slope", t, [](const State& st) { return st.y; }},
      {"trajectory", "x (m)", "y (m)", [](const State& st) { return st.x; },
       [](const State& st) { return st.y; }},
      {"v_x–t", "t (s)", "v_x (m/s)", t, [](const State& st) { return st.vx; }},
      {"v_y–t", "t (s)", "v_y (m/s)", t, [](const State& st) { return st.vy; }},
      {"a_x–t", "t (s)", "a_x (m/s^2)", t, [](const State& st) { return st.ax; }},
      {"a_y–t", "t (s)", "a_y (m/s^2)", t, [](const State& st) { return st.ay; }},
  };
  int added = 0;
  for (const Panel& p : panels) {
    Figure f;
    f.title = title + ": " + p.suffix;
    f.caption = caption;
    f.x_axis.title = p.x_title;
    f.y_axis.title = p.y_title;
    f.height_px = 340;
    f.equal_aspect = std::string(p.suffix) == "trajectory";
    for (const InclineCurve& c : curves) f.series.push_back(series_of(c, p.fx, p.fy));
    s.add_figure(std::move(f));
    ++added;
  }
  return added;
}

void add_model_b_equations(report::Section& s) {
  s.add_equation("α = g μ cos φ,   β = g sin φ,   k = tan φ / μ = β/α", "incline study, eqs 1.1, 1.2",
                 "friction deceleration, gravity along the slope and their ratio");
  s.add_equation("a_x = −α / cosh(k s),   a_y = α tanh(k s) − β,   s = −ln(v_x/v_{x0})",
                 "incline study, eqs 1, 4 (一, 四)", "model B: friction opposite the velocity");
  s.add_equation("v_y = −v_{x0} e^{−s} sinh(k s)", "incline study, eq 5 (五)");
  s.add_equation("t = v_{x0}/(2α) [E(1+k, s) + E(1−k, s)],   E(c, s) = (1 − e^{−c s})/c",
                 "incline study, eq 2 (二)");
  s.add_equation("x = v_{x0}^2/(2α) [E(2+k, s) + E(2−k, s)],   y = v_{x0}^2/(4α) [E(2+2k, s) − E(2−2k, s)]",
                 "incline study, eqs 3, 6 (三, 六)");
  s.add_equation("t_{stop} = v_{x0}/(α(1−k^2)),   x_{stop} = 2v_{x0}^2/(α(4−k^2)),   y_{stop} = −k v_{x0}^2/(4α(1−k^2))",
                 "incline study, eqs 7, 8, 9 (七, 八, 九)", "for k < 1; k = 1 tends to a terminal speed v0/2, k > 1 accelerates");
}

report::Table incline_parameter_table(const incline::Parameters& p) {
  Table t;
  t.caption = "Parameters";
  t.header = {"quantity", "value"};
  t.rows = {{"μ (kinetic friction coefficient)", report::format_value(p.mu, 5)},
            {"φ (incline angle), deg", deg(p.phi)},
            {"v_0 (launch speed along +x), m/s", report::format_value(p.v0, 5)},
            {"g, m/s^2", report::format_value(p.g, 5)},
            {"k = tan φ / μ", report::format_value(p.k(), 5)},
            {"regime", incline::to_string(p.regime())}};
  if (p.mu_static) t.rows.push_back({"μ_s (static)", report::format_value(*p.mu_static, 5)});
  if (p.normal_accel != 0)
    t.rows.push_back({"f_N/m (model A), m/s^2", report::format_value(p.normal_accel, 5)});
  return t;
}

report::Report incline_simulate_report(const incline::Parameters& p, bool model_a,
                                       const std::string& method,
                                       const std::vector<incline::State>& all_states,
                                       const std::vector<incline::State>& comparison,
                                       const std::string& comparison_name) {
  const std::vector<State> states = thin(all_states);
  report::Report r;
  r.title = "tribolab incline simulate";
  r.subtitle = std::string("Model ") + (model_a ? "A" : "B") + ", " + method + " method";
  auto& s = r.add_section("Launch across the incline");
  s.add_table(incline_parameter_table(p));
  if (model_a) {
    s.add_equation("dv/dt = −g cos φ μ v̂ + (f_N/m) n̂ − g sin φ ŷ,   dx/dt = v",
                   "incline study, section 4-3 (肆-三); docs/theory.md#numerical-model",
                   "model A: a friction component f_N normal to the path (n̂ = left normal of v̂)");
  } else {
    add_model_b_equations(s);
  }
  std::vector<InclineCurve> curves{{method == "analytic" ? "closed form (model B)" : "numeric",
                                    states, report::Mode::Lines, report::Dash::Solid, "#1f77b4"}};
  if (!model_a && !comparison.empty() && comparison.size() == states.size()) {
    curves.push_back(incline_curve(comparison_name, comparison, report::Dash::Dash, "#d62728"));
    double max_dx = 0, max_dy = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      max_dx = std::max(max_dx, std::abs(states[i].x - comparison[i].x));
      max_dy = std::max(max_dy, std::abs(states[i].y - comparison[i].y));
    }
    s.add_paragraph("Closed form and numerical integration overlaid (dashed): the largest "
                    "difference over the samples is " + report::format_value(max_dx, 3) +
                    " m in x and " + report::format_value(max_dy, 3) + " m in y.");
  }
  add_incline_kinematics(s, "Launch", curves);
  return r;
}

report::Report incline_families_report(const incline::FamilyOptions& options,
                                       const incline::Family& family) {
  report::Report r;
  r.title = "tribolab incline families";
  const bool phi = options.vary == incline::FamilyParameter::phi;
  const std::string name = incline::to_string(options.vary);
  r.subtitle = "Closed-form model B curves over " + name + " (incline study, figures 5–7 (五–七))";
  auto& s = r.add_section("Family over " + name);
  s.add_table(incline_parameter_table(options.base));
  add_model_b_equations(s);
  Table stops;
  stops.caption = "Stops of the members";
  stops.header = {phi ? "φ (deg)" : name, "k", "regime", "t_stop (s)", "x_stop (m)", "y_stop (m)"};
  std::vector<InclineCurve> curves;
  for (const auto& m : family.members) {
    const std::string shown = report::format_value(phi ? to_deg(m.value) : m.value, 4);
    curves.push_back(incline_curve(name + " = " + shown, thin(m.trajectory)));
    stops.rows.push_back({shown, report::format_value(m.prediction.k, 4),
                          incline::to_string(m.prediction.regime),
                          optional_number(m.prediction.t_stop, ""),
                          optional_number(m.prediction.x_stop, ""),
                          optional_number(m.prediction.y_stop, "")});
  }
  s.add_table(std::move(stops));
  if (!family.warnings.empty()) {
    std::vector<std::string> w;
    for (const auto& x : family.warnings) w.push_back("Warning: " + x);
    s.add_list(w);
  }
  add_incline_kinematics(s, "Family over " + name, curves);
  return r;
}

report::Report incline_predict_report(const incline::Parameters& p, const incline::Prediction& pr,
                                      const std::vector<incline::State>& trajectory) {
  report::Report r;
  r.title = "tribolab incline predict";
  r.subtitle = "Closed-form model B prediction (incline study)";
  auto& s = r.add_section("Prediction");
  s.add_table(incline_parameter_table(p));
  add_model_b_equations(s);
  Table key;
  key.caption = "Key numbers";
  key.header = {"quantity", "value"};
  key.rows = {{"regime", incline::to_string(pr.regime)},
              {"t_stop (s)", optional_number(pr.t_stop, "")},
              {"x_stop (m)", optional_number(pr.x_stop, "")},
              {"y_stop (m)", optional_number(pr.y_stop, "")},
              {"terminal speed (m/s)", optional_number(pr.v_terminal, "")},
              {"sup x (m)", optional_number(pr.x_limit, "")},
              {"a_x0, a_y0 (m/s^2)", report::format_value(pr.a_x0, 4) + ", " + report::format_value(pr.a_y0, 4)},
              {"final a_x, a_y (m/s^2)",
               report::format_value(pr.a_x_final, 4) + ", " + report::format_value(pr.a_y_final, 4)},
              {"a disc at rest stays", pr.stays_at_rest ? "yes" : "no"}};
  s.add_table(std::move(key));
  if (!trajectory.empty()) {
    add_incline_kinematics(s, "Trajectory", {incline_curve("closed form (model B)", trajectory)},
                           pr.t_stop ? "Up to 1.25 t_stop: the disc rests after the stop."
                                     : "Over 2 v0/α: the disc does not stop.");
  } else {
    s.add_paragraph("No trajectory drawn: the default duration is not finite for these parameters.");
  }
  return r;
}

}  // namespace tribolab::app
