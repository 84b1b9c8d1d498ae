// The incline case study of the demo (seed 000): table 1, figures 二, 四, 五, 六, 七 and 八 and
// the printed-number checks, each next to what tribolab computes (incline::seed000_case_study,
// the closed form, the numerical model and the families API).
#include "numerics/units.hpp"
#include "app/demo/demo.hpp"
#include "app/incline/report_incline.hpp"
#include "app/common/report_util.hpp"

#include "incline/case_study.hpp"
#include "incline/closed_form.hpp"
#include "incline/families.hpp"
#include "incline/numeric.hpp"
#include "report/format.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace tribolab::app {
namespace {

using incline::Parameters;
using report::format_value;

constexpr int kSamples = 240;  ///< samples per curve: smooth at report size, small file

Parameters setup(double mu, double phi_deg, double v0) {
  Parameters p;
  p.mu = mu;
  p.phi = to_rad(phi_deg);
  p.v0 = v0;
  p.g = kDefaultG;  // the seed's value
  return p;
}

std::vector<double> even_times(double t_end, int n) {
  std::vector<double> t(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) t[static_cast<std::size_t>(i)] = t_end * i / n;
  return t;
}

std::string pct(double x) { return format_value(x, 3) + " %"; }

void add_table1(report::Section& s, const incline::CaseStudy& cs, std::ostream& log) {
  s.add_equation("x_f/|y_f| = 8(1 − k^2)/(k(4 − k^2)),   μ_A = tan φ / k   (the root 0 < k < 1 of this cubic in k)",
                 "incline study, eq 10A (十A) (appendix 10.6)",
                 "solved by bracketing the cubic's physical root; the main-text form selects the wrong root (errata)");
  report::Table t;
  t.caption = "Table 1 (表一): μ from the stopping point vs μ_o = 0.634";
  t.header = {"φ (deg)", "x_f (m)", "|y_f| (m)", "μ_A printed", "μ_A tribolab", "difference",
              "(μ_A − μ_o)/μ_o printed", "tribolab"};
  log << "  table 1: phi_deg  mu_A(printed)  mu_A(tribolab)\n";
  for (const auto& row : cs.table1) {
    t.rows.push_back({format_value(row.phi_deg, 4), format_value(row.x_stop, 3), format_value(-row.y_stop, 3),
                      format_value(row.mu_printed, 3), format_value(row.mu, 4),
                      format_value(row.mu - row.mu_printed, 2), pct(row.diff_percent_printed), pct(row.diff_percent)});
    char line[128];
    std::snprintf(line, sizeof line, "    %6.2f  %.3f  %.4f\n", row.phi_deg, row.mu_printed, row.mu);
    log << line;
  }
  s.add_table(std::move(t));
  s.add_paragraph("μ_o from a straight slide (the study's eq a, φ = 41.09 deg, a = 1.758 m/s^2): printed 0.634, "
                  "tribolab " + format_value(cs.mu_o_from_eq_a, 4) + ".");
}

std::vector<InclineCurve> closed_form_curves(const std::vector<std::pair<std::string, Parameters>>& launches,
                                             double t_end) {
  std::vector<InclineCurve> curves;
  for (const auto& [name, p] : launches)
    curves.push_back(incline_curve(name, incline::ClosedForm(p).trajectory(even_times(t_end, kSamples))));
  return curves;
}

int add_family(report::Section& s, const std::string& title, const Parameters& base,
               incline::FamilyParameter vary, const std::vector<double>& values, const std::string& caption) {
  incline::FamilyOptions o;
  o.base = base;
  o.vary = vary;
  o.values = values;
  o.samples = kSamples;
  const incline::Family f = incline::make_family(o);
  std::vector<InclineCurve> curves;
  const bool phi = vary == incline::FamilyParameter::phi;
  for (const auto& m : f.members) {
    const std::string unit = phi ? " deg" : (vary == incline::FamilyParameter::v0 ? " m/s" : "");
    const double shown = phi ? to_deg(m.value) : m.value;
    curves.push_back(incline_curve(std::string(phi ? "φ" : (vary == incline::FamilyParameter::v0 ? "v0" : "μ")) + " = " +
                          format_value(shown, 4) + unit + " (" + incline::to_string(m.prediction.regime) + ")",
                      m.trajectory));
  }
  return add_incline_kinematics(s, title, curves, caption);
}

/// Figure 八: t_f ∝ v0, x_f and y_f ∝ v0^2, y_f vs x_f, with our slopes and the printed ones.
void add_figure8(report::Section& s, std::ostream& log) {
  // 圖八-2 and -4 use phi = 10.37 deg, 圖八-5 10.46 deg (mu = 0.585 throughout).
  const double mu = 0.585, phi_deg = 10.37, phi5_deg = 10.46;
  const incline::Prediction unit = incline::ClosedForm(setup(mu, phi_deg, 1.0)).predict();
  const incline::Prediction unit5 = incline::ClosedForm(setup(mu, phi5_deg, 1.0)).predict();
  const double st = *unit.t_stop, sx = *unit.x_stop, sy = *unit.y_stop;
  const double syx = *unit5.y_stop / *unit5.x_stop;
  // The seed's printed theory slopes (圖八-2, -4, -5).
  const double pt = 0.2242, px = 0.0948, py = -0.0155, pyx = -0.2123;
  std::vector<double> v0s;
  for (int i = 0; i <= 12; ++i) v0s.push_back(0.5 + 0.25 * i);
  struct Panel { std::string title, x_title, y_title; double ours, printed; bool squared, yx; double phi_deg; };
  const Panel panels[] = {
      {"The study's figure 8-2 (八-2): t_f ∝ v_0", "v_0 (m/s)", "t_f (s)", st, pt, false, false, phi_deg},
      {"The study's figure 8-4 (八-4): x_f ∝ v_0^2", "v_0^2 (m^2/s^2)", "x_f (m)", sx, px, true, false, phi_deg},
      {"The study's figure 8-4 (八-4): y_f ∝ v_0^2", "v_0^2 (m^2/s^2)", "y_f (m)", sy, py, true, false, phi_deg},
      {"The study's figure 8-5 (八-5): y_f vs x_f (φ 10.46 deg)", "x_f (m)", "y_f (m)", syx, pyx, false, true, phi5_deg},
  };
  report::Table t;
  t.caption = "The study's figure 8 (八) slopes (μ = 0.585, φ = 10.37 deg; 8-5 (八-5) at 10.46 deg): tribolab (closed form, eqs 7–10 (七–十)) vs printed";
  t.header = {"slope", "printed", "tribolab", "difference"};
  for (const Panel& p : panels) {
    report::Figure f;
    f.title = p.title;
    f.x_axis.title = p.x_title;
    f.y_axis.title = p.y_title;
    f.height_px = 340;
    report::Series ours = named("tribolab (closed form), slope " + format_value(p.ours, 4));
    report::Series printed = named("slope printed in the study, " + format_value(p.printed, 4));
    ours.mode = report::Mode::LinesMarkers;
    printed.mode = report::Mode::Lines;
    printed.dash = report::Dash::Dash;
    printed.color = "#d62728";
    for (double v0 : v0s) {
      const incline::Prediction pr = incline::ClosedForm(setup(mu, p.phi_deg, v0)).predict();
      double x = p.squared ? v0 * v0 : v0, y = 0;
      if (p.yx) {
        x = *pr.x_stop;
        y = *pr.y_stop;
      } else if (p.title.find("t_f") != std::string::npos) {
        y = *pr.t_stop;
      } else if (p.title.find("x_f") != std::string::npos) {
        y = *pr.x_stop;
      } else {
        y = *pr.y_stop;
      }
      ours.x.push_back(x);
      ours.y.push_back(y);
      printed.x.push_back(x);
      printed.y.push_back(p.printed * x);
    }
    f.series = {ours, printed};
    s.add_figure(std::move(f));
    t.rows.push_back({p.title.substr(p.title.find(':') + 2), format_value(p.printed, 4), format_value(p.ours, 4),
                      pct(100 * (p.printed - p.ours) / p.ours)});
  }
  s.add_table(std::move(t));
  log << "  figure 8 slopes (printed -> tribolab): t_f/v0 " << pt << " -> " << format_value(st, 4)
      << ", x_f/v0^2 " << px << " -> " << format_value(sx, 4) << ", y_f/v0^2 " << py << " -> "
      << format_value(sy, 4) << ", y_f/x_f " << pyx << " -> " << format_value(syx, 4) << '\n';
}

}  // namespace

void add_incline_case_study(report::Report& r, std::ostream& log) {
  const incline::CaseStudy cs = incline::seed000_case_study();

  auto& t1 = r.add_section("The incline study: table 1, μ from the stopping point");
  t1.add_paragraph("A disc launched along +x across an incline of angle φ slides with kinetic friction μ "
                   "opposite its velocity (model B, the study's conclusion). x is across the slope, y up the "
                   "slope (the disc moves to y < 0). The study measures μ from where the disc stops alone.");
  add_model_b_equations(t1);
  add_table1(t1, cs, log);

  auto& f2 = r.add_section("Incline: figures 2 and 4 (二, 四), rough vs smooth incline and model B");
  const Parameters rough = setup(0.634, 23.20, 2.30), smooth = setup(0.0, 23.20, 2.30);
  const double t2 = incline::default_duration(rough);
  f2.add_paragraph("Figure 2 (二): the same launch (φ = 23.20 deg, v0 = 2.30 m/s) on the rough incline (μ = 0.634) "
                   "and on a smooth one (μ = 0, a projectile on the incline: x = v0 t, y = −g sin φ t^2/2). "
                   "The rough disc stops at t = " + format_value(*incline::ClosedForm(rough).predict().t_stop, 4) +
                   " s and rests.");
  add_incline_kinematics(f2, "The study's figure 2 (二) (φ 23.20 deg, v0 2.30 m/s)",
                         closed_form_curves({{"rough, μ = 0.634", rough}, {"smooth, μ = 0", smooth}}, t2));
  // Figure 四: model B's curves, closed form vs the independent numerical integration.
  const std::vector<double> times = even_times(t2, kSamples);
  const incline::NumericResult num = incline::simulate(rough, times);
  std::vector<InclineCurve> model_b{incline_curve("closed form (eqs 1–9 (一–九))", incline::ClosedForm(rough).trajectory(times))};
  if (num.status != incline::NumericStatus::failed) {
    model_b.push_back(incline_curve("numerical integration (Dormand–Prince 5(4))", num.samples,
                                    report::Dash::Dash, "#d62728"));
  }
  double max_diff = 0;
  if (model_b.size() == 2 && model_b[1].states.size() == model_b[0].states.size()) {
    for (std::size_t i = 0; i < model_b[0].states.size(); ++i)
      max_diff = std::max({max_diff, std::abs(model_b[0].states[i].x - model_b[1].states[i].x),
                           std::abs(model_b[0].states[i].y - model_b[1].states[i].y)});
  }
  f2.add_paragraph("Figure 4 (四): model B on the rough incline, the closed form and a numerical integration of the "
                   "equations of motion overlaid; largest position difference " + format_value(max_diff, 2) + " m.");
  add_incline_kinematics(f2, "The study's figure 4 (四) (model B, μ 0.634)", model_b);

  auto& f5 = r.add_section("Incline: figures 5, 6, 7 (五, 六, 七), families of curves");
  f5.add_paragraph("Closed-form curves over one parameter with the others fixed (incline families). k = tan φ/μ: "
                   "k < 1 stops, k = 1 tends to the terminal speed v0/2, k > 1 accelerates.");
  add_family(f5, "The study's figure 5 (五) (over v0; φ 20.96 deg, μ 0.634)", setup(0.634, 20.96, 2.62),
             incline::FamilyParameter::v0, {1.0, 1.5, 2.0, 2.62, 3.0}, "t_f ∝ v0, x_f and y_f ∝ v0^2 (figure 8 (八)).");
  add_family(f5, "The study's figure 6 (六) (over φ; v0 2.620 m/s, μ 0.634)", setup(0.634, 20.96, 2.62),
             incline::FamilyParameter::phi,
             {to_rad(10.0), to_rad(20.96), std::atan(0.634), to_rad(40.0)},
             "φ = atan 0.634 = 32.37 deg is the k = 1 boundary.");
  add_family(f5, "The study's figure 7 (七) (over μ; φ 20.96 deg, v0 2.620 m/s)", setup(0.634, 20.96, 2.62),
             incline::FamilyParameter::mu, {0.0, 0.2, std::tan(to_rad(20.96)), 0.5, 0.634},
             "μ = tan 20.96 deg = 0.383 is the k = 1 boundary; μ = 0 is the smooth incline.");

  auto& f8 = r.add_section("Incline: figure 8 (八), scaling of the stop with v0");
  f8.add_paragraph("From eqs 7–9 (七–九), t_f is proportional to v0 and x_f, y_f to v0^2, so y_f/x_f depends on k "
                   "alone (eq 10 (十)). The study's printed theory slopes do not follow from its own equations "
                   "(errata); the points are tribolab's closed form, the dashed lines the printed slopes.");
  add_figure8(f8, log);

  auto& chk = r.add_section("Incline: printed numbers checked");
  report::Table t;
  t.caption = "Numbers printed in the incline study, recomputed independently";
  t.header = {"where", "printed", "tribolab", "agrees?", "how"};
  int agree = 0;
  for (const auto& c : cs.checks) {
    t.rows.push_back({c.where, format_value(c.printed, 5), format_value(c.computed, 5),
                      c.agrees ? "yes" : "no", c.note});
    agree += c.agrees ? 1 : 0;
  }
  chk.add_table(std::move(t));
  chk.add_paragraph("A printed number agrees when it equals tribolab's value to half a unit of its last digit.");
  log << "  printed numbers: " << agree << " of " << cs.checks.size() << " agree (the others are errata)\n";
}

}  // namespace tribolab::app
