#include "app/bounce/report_bounce_analysis.hpp"

#include "app/bounce/report_bounce.hpp"
#include "app/common/report_util.hpp"

#include "bounce/geometry.hpp"
#include "bounce/normal_law.hpp"
#include "numerics/units.hpp"
#include "report/format.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace tribolab::app {
namespace {

using analysis::BounceAnalysis;
using analysis::SegmentFit;
using report::Figure;
using report::format_uncertain;
using report::format_value;
using report::Series;
using report::Table;



Figure analysis_figure(std::string title, std::string x, std::string y, int height = 380) {
  return make_figure(std::move(title), std::move(x), std::move(y), height);
}

bool fitted(const BounceAnalysis& r, std::size_t i) {
  return (i >= r.pre.begin && i < r.pre.end) || (i >= r.post.begin && i < r.post.end);
}

/// Per-frame data of the body as series: fitted frames (centre) and the others (grey).
void add_data(Figure& f, const BounceAnalysis& r, const std::string& what,
              const std::function<double(const track::RigidBodyRow&)>& value,
              const std::function<double(const track::RigidBodyRow&)>& error = {}) {
  Series in = named(what + ", fitted frames"), out = named(what + ", not fitted (contact, other flights)");
  out.color = "#aaaaaa";
  for (std::size_t i = 0; i < r.body.rows.size(); ++i) {
    const auto& row = r.body.rows[i];
    Series& s = fitted(r, i) ? in : out;
    s.x.push_back(row.t);
    s.y.push_back(value(row));
    if (error) s.y_error.push_back(error(row));
  }
  f.series.push_back(std::move(in));
  if (!out.x.empty()) f.series.push_back(std::move(out));
}

/// The fitted curve of one segment on its grid.
Series fit_curve(const SegmentFit& seg, const std::string& name, const std::vector<double>& y, double scale = 1) {
  Series s = named(name, report::Mode::Lines);
  s.x = seg.grid_t;
  for (double v : y) s.y.push_back(scale * v);
  return s;
}

/// A dotted vertical line at the impact time spanning the y range of the figure's series.
void mark_time(Figure& f, double t, const char* name, report::Dash dash, const char* color) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : f.series)
    for (double y : s.y)
      if (std::isfinite(y)) {
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
  if (!std::isfinite(lo)) return;
  Series m = named(name, report::Mode::Lines);
  m.dash = dash;
  m.color = color;
  m.x = {t, t};
  m.y = {lo, hi};
  f.series.push_back(std::move(m));
}

/// Vertical lines at the first touch, the impact time (impulse centroid) and the separation.
void mark_impact(Figure& f, const BounceAnalysis& r) {
  const std::size_t n = f.series.size();
  mark_time(f, r.t_touch, "first touch", report::Dash::Dash, "gray");
  // The marks' extent is taken from the data only, not from the marks added here.
  auto extent = f.series.back().y;
  mark_time(f, r.impact_time, "impact time (impulse centroid)", report::Dash::Dot, "black");
  mark_time(f, r.t_separation, "separation", report::Dash::Dash, "gray");
  for (std::size_t i = n; i < f.series.size(); ++i) f.series[i].y = extent;
}

/// Tip positions from the body row: A = centre - (L/2) u, B = centre + (L/2) u.
double tip(const track::RigidBodyRow& row, int sign, bool y) {
  const double h = 0.5 * row.length * sign;
  return y ? row.yc + h * std::sin(row.theta) : row.xc + h * std::cos(row.theta);
}

void add_tips(Figure& f, const BounceAnalysis& r, bool y) {
  for (int sign : {-1, 1}) {
    Series s = named("tip " + (sign < 0 ? r.body.point_a : r.body.point_b));
    for (const auto& row : r.body.rows) {
      s.x.push_back(row.t);
      s.y.push_back(tip(row, sign, y));
    }
    f.series.push_back(std::move(s));
  }
}

std::string r2(double v) { return format_value(v, 6); }

}  // namespace

int add_bounce_analysis_figures(report::Section& s, const std::string& title, const BounceAnalysis& r) {
  const double ti = r.impact_time;
  {
    Figure f = analysis_figure(title + ": x–t", "t (s)", "x (m)");
    add_tips(f, r, false);
    add_data(f, r, "centre", [](const auto& row) { return row.xc; });
    f.series.push_back(fit_curve(r.pre, "x–t line before", r.pre.grid_x));
    f.series.push_back(fit_curve(r.post, "x–t line after", r.post.grid_x));
    mark_impact(f, r);
    f.caption = "Tips, centre (their midpoint) and the fitted lines x = x_0 + v_x (t − t_i); R² = " +
                r2(r.pre.x_line.r_squared) + " before, " + r2(r.post.x_line.r_squared) + " after.";
    s.add_figure(std::move(f));
  }
  {
    Figure f = analysis_figure(title + ": y–t", "t (s)", "y (m)");
    add_tips(f, r, true);
    add_data(f, r, "centre", [](const auto& row) { return row.yc; });
    f.series.push_back(fit_curve(r.pre, "y–t parabola before", r.pre.grid_y));
    f.series.push_back(fit_curve(r.post, "y–t parabola after", r.post.grid_y));
    mark_impact(f, r);
    f.caption = "Tips, centre and the fitted parabolas y = y_0 + v_y (t − t_i) + a_y (t − t_i)²/2; R² = " +
                r2(r.pre.y_parabola.r_squared) + " before, " + r2(r.post.y_parabola.r_squared) +
                " after. The impact time t_i is where the parabolas meet; first touch and separation (dashed) where "
                "the lowest point of each flight, y − Y(θ), is on the floor.";
    s.add_figure(std::move(f));
  }
  {
    Figure f = analysis_figure(title + ": trajectory", "x (m)", "y (m)");
    f.equal_aspect = true;
    for (int sign : {-1, 1}) {
      Series t = named("tip " + (sign < 0 ? r.body.point_a : r.body.point_b));
      for (const auto& row : r.body.rows) {
        t.x.push_back(tip(row, sign, false));
        t.y.push_back(tip(row, sign, true));
      }
      f.series.push_back(std::move(t));
    }
    Series c = named("centre");
    for (const auto& row : r.body.rows) {
      c.x.push_back(row.xc);
      c.y.push_back(row.yc);
    }
    f.series.push_back(std::move(c));
    for (const SegmentFit* seg : {&r.pre, &r.post}) {
      Series fit = named(seg == &r.pre ? "fitted flight before" : "fitted flight after", report::Mode::Lines);
      fit.x = seg->grid_x;
      fit.y = seg->grid_y;
      f.series.push_back(std::move(fit));
    }
    Series floor = named("floor (" + std::string(r.floor_given ? "given" : "from the flights") + ")", report::Mode::Lines);
    floor.color = "black";
    floor.x = {c.x.empty() ? 0 : *std::min_element(c.x.begin(), c.x.end()),
               c.x.empty() ? 0 : *std::max_element(c.x.begin(), c.x.end())};
    floor.y = {r.floor_y, r.floor_y};
    f.series.push_back(std::move(floor));
    f.caption = "The path of the tips and the centre in the plane of the video (equal scales).";
    s.add_figure(std::move(f));
  }
  {
    Figure f = analysis_figure(title + ": residuals of the flight fits", "t (s)", "data − fit (mm)");
    for (const SegmentFit* seg : {&r.pre, &r.post}) {
      const std::string when = seg == &r.pre ? " before" : " after";
      Series rx = named("x" + when), ry = named("y" + when);
      for (std::size_t i = seg->begin; i < seg->end; ++i) {
        const auto& row = r.body.rows[i];
        rx.x.push_back(row.t);
        ry.x.push_back(row.t);
        rx.y.push_back(1e3 * (row.xc - seg->x_line(row.t - ti)));
        ry.y.push_back(1e3 * (row.yc - seg->y_parabola(row.t - ti)));
      }
      f.series.push_back(std::move(rx));
      f.series.push_back(std::move(ry));
    }
    mark_impact(f, r);
    f.caption = "Centre minus fitted line (x) or parabola (y) on the fitted frames; rms " +
                format_value(1e3 * r.pre.x_line.rms) + " / " + format_value(1e3 * r.pre.y_parabola.rms) + " mm before, " +
                format_value(1e3 * r.post.x_line.rms) + " / " + format_value(1e3 * r.post.y_parabola.rms) +
                " mm after (x / y). A trend here would mean a contact frame was kept.";
    s.add_figure(std::move(f));
  }
  {
    Figure f = analysis_figure(title + ": orientation θ–t", "t (s)", "θ of A→B (deg, unwrapped)");
    add_data(f, r, "θ", [](const auto& row) { return kDegPerRad * row.theta; });
    f.series.push_back(fit_curve(r.pre, "θ = θ_ref + ω t before", r.pre.grid_theta, kDegPerRad));
    f.series.push_back(fit_curve(r.post, "θ = θ_ref + ω t after", r.post.grid_theta, kDegPerRad));
    mark_impact(f, r);
    f.caption = "Orientation of the line from tip A to tip B, unwrapped, with the fitted spin lines; θ at the "
                "first touch = " + format_uncertain(r.theta_touch_deg, r.sigma_theta_touch_deg) + " deg, at the impact time " +
                format_value(r.theta_impact_deg) + " deg (wrapped).";
    s.add_figure(std::move(f));
  }
  {
    Figure f = analysis_figure(title + ": spin ω–t", "t (s)", "ω (rad/s), CCW positive");
    add_data(f, r, "local ω (±1 s.e.)", [](const auto& row) { return row.omega; },
             [](const auto& row) { return row.sigma_omega; });
    for (const SegmentFit* seg : {&r.pre, &r.post}) {
      Series w = named(seg == &r.pre ? "fitted ω before" : "fitted ω after", report::Mode::Lines);
      w.x = {seg->grid_t.front(), seg->grid_t.back()};
      w.y = {seg->omega, seg->omega};
      f.series.push_back(std::move(w));
    }
    mark_impact(f, r);
    f.caption = "Spin from a short sliding window of θ per frame, and the slope of each fitted θ line "
                "(constant in flight).";
    s.add_figure(std::move(f));
  }
  return 6;
}

report::Table bounce_segments_table(const BounceAnalysis& r) {
  Table t;
  t.caption = "Before and after the impact (± one standard uncertainty; v_x and ω are constant in flight, v_y at "
              "the impact time and, below, at the first touch / separation; energies at the first touch / separation)";
  t.header = {"quantity", "before", "after"};
  auto row = [&](const std::string& name, const std::function<std::string(const SegmentFit&)>& f) {
    t.rows.push_back({name, f(r.pre), f(r.post)});
  };
  row("v_x (m/s)", [](const SegmentFit& s) { return format_uncertain(s.vx, s.sigma_vx); });
  row("v_y (m/s)", [](const SegmentFit& s) { return format_uncertain(s.vy, s.sigma_vy); });
  row("ω (rad/s)", [](const SegmentFit& s) { return format_uncertain(s.omega, s.sigma_omega); });
  t.rows.push_back({"v_y at first touch / separation (m/s)", format_uncertain(r.vy_touch, r.sigma_vy_touch),
                    format_uncertain(r.vy_separation, r.sigma_vy_separation)});
  row("a_y (m/s²)", [](const SegmentFit& s) { return format_uncertain(s.acceleration_y, s.sigma_acceleration_y); });
  row("R² of x–t", [](const SegmentFit& s) { return r2(s.x_line.r_squared); });
  row("R² of y–t", [](const SegmentFit& s) { return r2(s.y_parabola.r_squared); });
  row("frames fitted", [](const SegmentFit& s) { return std::to_string(s.n_points); });
  row("apex time (s)", [](const SegmentFit& s) { return format_value(s.apex_time); });
  row("apex height above the floor (m)", [](const SegmentFit& s) { return format_uncertain(s.apex_height, s.sigma_apex_height); });
  row("kinetic energy, translational (J)", [](const SegmentFit& s) { return format_value(s.energy.translational_x + s.energy.translational_y); });
  row("kinetic energy, rotational (J)", [](const SegmentFit& s) { return format_value(s.energy.rotational); });
  row("kinetic energy, total (J)", [](const SegmentFit& s) { return format_value(s.energy.total()); });
  return t;
}

report::Table bounce_restitution_table(const BounceAnalysis& r) {
  Table t;
  t.caption = "Restitution, orientation and energy at the first touch (± one standard uncertainty)";
  t.header = {"quantity", "value", "note"};
  t.rows.push_back({"first touch t_c (s)", format_uncertain(r.t_touch, r.sigma_t_touch),
                    "lowest point of the pre-impact flight on the floor"});
  t.rows.push_back({"separation t_s (s)", format_uncertain(r.t_separation, r.sigma_t_separation),
                    "lowest point of the post-impact flight leaves the floor"});
  t.rows.push_back({"contact duration (s)", format_uncertain(r.contact_duration, r.sigma_contact_duration),
                    r.floor_method == analysis::FloorMethod::contact_duration ? "given (--contact-duration)" : "t_s − t_c"});
  t.rows.push_back({"impact time t_i (s)", format_value(r.impact_time), "where the two y–t parabolas meet (impulse centroid)"});
  t.rows.push_back({"e from velocities", format_uncertain(r.e_velocity, r.sigma_e_velocity),
                    "−v_y(t_s) / v_y(t_c): as bounce simulate"});
  t.rows.push_back({"e at one instant", format_uncertain(r.e_velocity_common, r.sigma_e_velocity_common),
                    "−v_y,after(t_i) / v_y,before(t_i): gravity between touch and separation biases it up"});
  const std::string floor_note =
      r.floor_method == analysis::FloorMethod::given ? "--floor-y"
      : r.floor_method == analysis::FloorMethod::contact_duration
          ? "where both flights touch the floor a contact duration apart"
          : "middle of a ±" + format_value(1e3 * r.floor_half_width) + " mm bracket from the flights (not trusted for e)";
  t.rows.push_back({"e from apex heights", format_uncertain(r.e_height, r.sigma_e_height),
                    r.floor_method == analysis::FloorMethod::bracket
                        ? "not reported: the floor estimated without --floor-y or --contact-duration is not "
                          "reliable enough (docs/theory.md#bounce-analysis)"
                        : "sqrt(H'/H)"});
  t.rows.push_back({"floor y (m)", format_value(r.floor_y), floor_note});
  t.rows.push_back({"θ at the first touch (deg)", format_uncertain(r.theta_touch_deg, r.sigma_theta_touch_deg),
                    "pre-impact spin line at t_c"});
  t.rows.push_back({"collision angle (deg)", format_uncertain(r.collision_angle_deg, r.sigma_collision_angle_deg),
                    "at the first touch, the rugby-ball study's figure 30 (三十) (as bounce simulate and sweep)"});
  t.rows.push_back({"θ, collision angle at t_i (deg)", format_value(r.theta_impact_deg) + ", " + format_value(r.collision_angle_impact_deg),
                    "at the impact time, for comparison only"});
  t.rows.push_back({"contact point speed at touch (m/s)", format_uncertain(r.contact_point_speed, r.sigma_contact_point_speed),
                    "(v_x, v_y) = (" + format_value(r.contact_point_vx) + ", " + format_value(r.contact_point_vy) +
                        "): centre velocity + ω × r_contact, the rugby-ball study's figure 52"});
  const double e0 = r.pre.energy.total(), e1 = r.post.energy.total();
  t.rows.push_back({"kinetic energy before → after (J)", format_value(e0) + " → " + format_value(e1),
                    "change " + format_value(e1 - e0) + " J (" + format_value(100 * (e1 - e0) / e0) + " %)"});
  t.rows.push_back({"rotational → translational (J)",
                    format_value(r.pre.energy.rotational - r.post.energy.rotational),
                    "rotational energy lost in the contact"});
  if (r.mean_normal_force) {
    t.rows.push_back({"mean normal force (N)", format_uncertain(*r.mean_normal_force, *r.sigma_mean_normal_force),
                      std::string("impulse / T, T ") + (r.force_duration_method == analysis::ForceDurationMethod::given ? "given" : "= t_s − t_c") +
                          " (its uncertainty included)"});
  }
  t.rows.push_back({"g seen by the flights (m/s²)", format_uncertain(r.gravity, r.sigma_gravity),
                    "tilt " + format_uncertain(r.gravity_tilt_deg, r.sigma_gravity_tilt_deg) +
                        " deg; 9.8 and 0 expected (frame rate, level camera)"});
  for (const auto& w : r.warnings) t.rows.push_back({"warning", w, ""});
  t.rows.push_back({"tip distance (m)", format_uncertain(r.body.length_mean, r.body.length_sd),
                    "mean ± sd over frames; should be 2a"});
  t.rows.push_back({"position noise of the centre (mm)", format_value(1e3 * r.impacts.noise_y), "robust estimate"});
  return t;
}

void add_bounce_analysis_equations(report::Section& s, const BounceAnalysis& r) {
  s.add_equation("x_c = (x_A + x_B)/2,   y_c = (y_A + y_B)/2,   θ = atan2(y_B − y_A, x_B − x_A)",
                 "rugby-ball study, experiment 1 (1) (實驗一 (一))", "centre from the two tracked tips; θ unwrapped over the frames");
  s.add_equation("x = x_0 + v_x (t − t_i)", "rugby-ball study, experiment 1 (實驗一) (x = vt + x_0)",
                 "one line per flight; v_x at the impact is the slope");
  s.add_equation("y = y_0 + v_y (t − t_i) + a_y (t − t_i)^2 / 2", "rugby-ball study, experiment 1 (實驗一) (y = at^2/2 + v_0 t + y_0)",
                 "one parabola per flight; t_i where they meet (the centroid of the normal impulse)");
  s.add_equation("θ = θ_{ref} + ω (t − t_{ref})", "docs/theory.md#bounce-analysis",
                 "the study reads ω = 2π/T from the period; a line through every frame gives its uncertainty");
  s.add_equation("e_v = −v_{y,after}(t_s) / v_{y,before}(t_c)", "rugby-ball study, experiment 1 (實驗一) (恢復係數 e, the coefficient of restitution); docs/theory.md#bounce-analysis",
                 "velocities at the first touch and at the separation, as the contact model defines e");
  s.add_equation("y_{before}(t_c) − Y(θ_{before}(t_c)) = y_{floor} = y_{after}(t_s) − Y(θ_{after}(t_s))",
                 "docs/theory.md#bounce-analysis", "first touch t_c and separation t_s on the fitted flights");
  s.add_equation("e_h = sqrt(H'/H),   H = y_0 − v_y^2/(2 a_y) − y_{floor}", "rugby-ball study, experiment 2 (3) (實驗二 (三))",
                 r.floor_given ? "apex heights of the centre above the given floor"
                               : "floor from the lowest point h = y − Y(θ) of the flights; see docs/theory.md#bounce-analysis");
  if (r.floor_method == analysis::FloorMethod::contact_duration) {
    s.add_equation("h_{pre}(t_c) = y_{floor} = h_{post}(t_c + T),   h = y − Y(θ),   t_i − T ≤ t_c ≤ t_i",
                   "docs/theory.md#bounce-analysis", "the floor from the flights: touch at t_c, separation T later");
  }
  s.add_equation("Y(θ) = sqrt(a^2 sin^2 θ + b^2 cos^2 θ)", "rugby-ball study, eq 20", "depth of the lowest point below the centre");
  s.add_equation("E = m v_x^2/2 + m v_y^2/2 + I ω^2/2", "rugby-ball study, discussion (討論)", "kinetic energy, translational and rotational");
  if (r.mean_normal_force) {
    s.add_equation("N_{mean} = m (v_{y,after}(t_i) − v_{y,before}(t_i)) / T = m (v_y(t_s) − v_y(t_c)) / T + m g",
                   "rugby-ball study, experiment 1 (實驗一); docs/theory.md#bounce-analysis",
                   "the impulse over the contact duration T (given, or t_s − t_c)");
  }
}

report::Report bounce_analyze_report(const std::string& command, const bounce::Ball& ball, const BounceAnalysis& r) {
  report::Report rep;
  rep.title = "tribolab bounce analyze";
  rep.subtitle = command;
  auto& s = rep.add_section("Tracked bounce: data and fits");
  s.add_paragraph("The rugby-ball study's experiment 1 on the tracked tips: " + std::to_string(r.body.rows.size()) +
                  " frames, " + std::to_string(r.impacts.impacts.size()) + " impact(s) detected, impact " +
                  std::to_string(r.impact_used + 1) + " analysed. Frames in contact with the floor are "
                  "dropped automatically (grey); times are real seconds (after --time-scale).");
  add_bounce_analysis_figures(s, "Bounce", r);
  auto& res = rep.add_section("Results");
  res.add_table(bounce_segments_table(r));
  res.add_table(bounce_restitution_table(r));
  auto& eq = rep.add_section("Ball and equations");
  eq.add_table(ball_table(ball));
  add_bounce_analysis_equations(eq, r);
  return rep;
}

int add_bounce_fit_figures(report::Section& s, const std::string& title,
                           const std::vector<analysis::BounceRow>& rows, const analysis::BounceFitResult& r) {
  struct Quantity {
    const char* name;
    const char* axis_name;  ///< in the axes' notation: a subscript longer than one letter in braces
    const char* unit;
    double analysis::BounceRow::*measured;
    double analysis::BounceFitRow::*predicted;
  };
  const Quantity qs[] = {{"v_x,out", "v_{x,out}", "m/s", &analysis::BounceRow::vx_out, &analysis::BounceFitRow::vx_pred},
                         {"v_y,out", "v_{y,out}", "m/s", &analysis::BounceRow::vy_out, &analysis::BounceFitRow::vy_pred},
                         {"ω_out", "ω_{out}", "rad/s", &analysis::BounceRow::omega_out, &analysis::BounceFitRow::omega_pred}};
  for (const Quantity& q : qs) {
    Figure f = analysis_figure(title + ": " + q.name + " measured vs fitted", std::string("measured ") + q.axis_name + " (" + q.unit + ")",
                      std::string("fitted model ") + q.axis_name + " (" + q.unit + ")");
    Series pts = named("bounces");
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const double m = rows[i].*q.measured, p = r.rows[i].*q.predicted;
      pts.x.push_back(m);
      pts.y.push_back(p);
      for (double v : {m, p})
        if (std::isfinite(v)) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
    }
    f.series.push_back(std::move(pts));
    if (std::isfinite(lo)) {
      Series diag = named("fitted = measured", report::Mode::Lines);
      diag.color = "black";
      diag.dash = report::Dash::Dot;
      diag.x = {lo, hi};
      diag.y = {lo, hi};
      f.series.push_back(std::move(diag));
    }
    f.equal_aspect = true;
    f.caption = "Each point is one bounce of the table: the measured outgoing value against the fitted "
                "law's prediction from the same incoming state. Points on the dotted line are fitted exactly.";
    s.add_figure(std::move(f));
  }
  auto residual_figure = [&](const std::string& suffix, const std::string& x_title,
                             const std::function<double(std::size_t)>& x) {
    Figure f = analysis_figure(title + ": residuals " + suffix, x_title, "fitted − measured (m/s)");
    Series a = named("v_x"), b = named("v_y"), c = named("b ω");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      for (Series* se : {&a, &b, &c}) se->x.push_back(x(i));
      a.y.push_back(r.rows[i].r_vx);
      b.y.push_back(r.rows[i].r_vy);
      c.y.push_back(r.rows[i].r_b_omega);
    }
    f.series = {std::move(a), std::move(b), std::move(c)};
    f.caption = "Residuals of the outgoing v_x, v_y and of ω times the semi-minor axis b (a surface speed), "
                "the quantities the fit minimises; rms " + format_value(r.rms) + " m/s. A trend would show a law that "
                "misses part of the physics.";
    s.add_figure(std::move(f));
  };
  residual_figure("by row", "row of the table", [](std::size_t i) { return static_cast<double>(i + 1); });
  residual_figure("against the orientation at touch", "θ at touch (deg)",
                  [&](std::size_t i) { return rows[i].theta_deg; });
  return 5;
}

report::Table bounce_fit_parameters_table(const analysis::BounceFitOptions& o, const analysis::BounceFitResult& r) {
  auto is_free = [&](const std::string& name) {
    return std::find(r.free_parameters.begin(), r.free_parameters.end(), name) != r.free_parameters.end();
  };
  Table t;
  t.caption = "Fitted contact law (± one standard uncertainty; fixed parameters have none)";
  t.header = {"parameter", "value", "status"};
  auto row = [&](const std::string& name, const std::string& label, double v, double sigma) {
    const bool free = is_free(name);
    t.rows.push_back({label, free ? format_uncertain(v, sigma) : format_value(v), free ? "fitted" : "fixed"});
  };
  const bool hooke = o.model == bounce::NormalModel::hooke;
  row("K", hooke ? "K (N/m)" : "K (N/m^n)", r.K, r.sigma_K);
  row("n", "n", r.n, r.sigma_n);
  if (o.restitution_model) {
    row("e", "e (target restitution)", r.e, r.sigma_e);
  } else {
    row("D", hooke ? "D (N s/m)" : "D (N s/m^(n+1))", r.D, r.sigma_D);
  }
  row("mu", "μ", r.mu, r.sigma_mu);
  t.rows.push_back({"rms of the residuals (m/s)", format_value(r.rms), "over 3 × " + std::to_string(r.rows.size()) + " residuals"});
  t.rows.push_back({"degrees of freedom", std::to_string(r.fit.dof), std::to_string(r.fit.iterations) + " iterations"});
  return t;
}

void add_bounce_fit_equations(report::Section& s, const std::vector<analysis::BounceRow>& rows,
                              const analysis::BounceFitOptions& o, const analysis::BounceFitResult& r) {
  bounce::NormalLawSpec spec;
  spec.model = o.model;
  spec.K = r.K;
  spec.n = r.n;
  if (o.restitution_model) {
    spec.restitution = r.e;
  } else {
    spec.D = r.D;
  }
  std::vector<double> speeds;
  for (const auto& row : rows) speeds.push_back(std::abs(row.vy_in));
  std::nth_element(speeds.begin(), speeds.begin() + speeds.size() / 2, speeds.end());
  const double v_med = speeds.empty() ? 1.0 : speeds[speeds.size() / 2];
  add_contact_equations(s, bounce::resolve(spec, v_med, o.ball.mass));
  if (o.restitution_model) {
    s.add_paragraph("Restitution-based law: D follows from the fitted e and each bounce's incoming speed "
                    "(docs/theory.md#hunt-crossley-restitution); the D shown is at the median |v_y,in| = " +
                    format_value(v_med) + " m/s.");
  }
  s.add_equation("r = (v_{x,pred} − v_{x,out},  v_{y,pred} − v_{y,out},  b (ω_{pred} − ω_{out}))", "docs/theory.md#bounce-fit",
                 "residuals of each bounce, all in m/s; minimised with a robust loss");
}

report::Report bounce_fit_report(const std::string& command, const std::vector<analysis::BounceRow>& rows,
                                 const analysis::BounceFitOptions& o, const analysis::BounceFitResult& r) {
  report::Report rep;
  rep.title = "tribolab bounce fit";
  rep.subtitle = command;
  auto& s = rep.add_section("Contact-law fit");
  s.add_paragraph("Each of the " + std::to_string(rows.size()) + " bounces is simulated from its incoming state "
                  "with the law below (" + std::string(bounce::to_string(o.friction.kind)) +
                  " friction) and compared with the measured outgoing state (rugby-ball study, research methods 6 (研究方法 六): the study "
                  "fitted K, n and D to its measurements the same way).");
  s.add_table(bounce_fit_parameters_table(o, r));
  if (!r.warnings.empty()) {  // docs/theory.md#plausibility-checks
    std::vector<std::string> w;
    for (const auto& x : r.warnings) w.push_back("Warning: " + x);
    s.add_list(w);
  }
  add_bounce_fit_figures(s, "Fit", rows, r);
  auto& eq = rep.add_section("Ball and equations");
  eq.add_table(ball_table(o.ball));
  add_bounce_fit_equations(eq, rows, o, r);
  Table t;
  t.caption = "Bounces: measured and fitted outgoing state";
  t.header = {"row", "θ (deg)", "v_{x,in}", "v_{y,in}", "ω_{in}", "v_{x,out}", "fitted", "v_{y,out}", "fitted", "ω_{out}", "fitted"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& m = rows[i];
    const auto& p = r.rows[i];
    t.rows.push_back({std::to_string(i + 1), format_value(m.theta_deg), format_value(m.vx_in), format_value(m.vy_in), format_value(m.omega_in),
                      format_value(m.vx_out), format_value(p.vx_pred), format_value(m.vy_out), format_value(p.vy_pred), format_value(m.omega_out), format_value(p.omega_pred)});
  }
  eq.add_table(std::move(t));
  return rep;
}

}  // namespace tribolab::app
