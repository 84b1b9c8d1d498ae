// The bounce case study of the demo (seed 001): the support geometry (correct vs the seed's
// formula), table 4 (contact times), figures 45-48 (one contact), a drop that rises above its
// release height, and the heat maps of figures 53-56 with the e = 1 boundary.
#include "app/demo/demo.hpp"
#include "app/bounce/bounce_cell.hpp"
#include "app/bounce/report_bounce.hpp"
#include "app/sweep/report_sweep.hpp"
#include "app/common/report_util.hpp"

#include "bounce/contact.hpp"
#include "bounce/drop.hpp"
#include "bounce/flight.hpp"
#include "bounce/geometry.hpp"
#include "bounce/impact.hpp"
#include "numerics/units.hpp"
#include "report/format.hpp"
#include "sweep/contour.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

namespace tribolab::app {
namespace {

using namespace tribolab::bounce;
using report::format_value;


/// The seed's fitted law (研究方法 六): N = 101054 d^1.51 + 60423 d^1.51 d'.
NormalLawSpec seed_law() { return NormalLawSpec{}; }

/// A low-damping law with the seed's K and n (D = 6000 N s/m^2.51, a tenth of the seed's): the
/// contact returns most of the energy it stores, so spin can lift the ball above its drop
/// height. At v_y = -4 m/s about two thirds of the map 100-170 deg x 30-50 rad/s has e > 1,
/// so the e = 1 boundary lies inside it (D = 3000 puts the whole map above 1).
NormalLawSpec low_damping_law() {
  NormalLawSpec s;
  s.D = 6000;
  return s;
}


/// The demo's impact convention for the maps (docs/cli.md, demo): the seed's collision angle
/// with the ball moving to +x (direction +1, v_x = 0 at touch), clockwise spin (omega < 0,
/// the sense that reproduces table 4 row 1), incoming v_y = -speed.
BodyState impact(const Ball& ball, double collision_angle_deg, double spin, double speed) {
  BodyState s;
  s.theta = theta_for_collision_angle(ball, collision_angle_deg, 1);
  s.vy = -speed;
  s.omega = -spin;
  return s;
}

/// The maps' cell: the one bounce cell model of `bounce sweep` (app/bounce/bounce_cell.hpp), the whole
/// impact from first touch with the demo's convention (impact(): collision angle, ball moving to
/// +x, clockwise spin), the given law and tolerance 1e-8.
sweep::CellModel contact_model(const NormalLawSpec& law, const std::string& name) {
  BounceCellOptions o;
  o.law.K = law.K;
  o.law.n = law.n;
  o.law.D = law.D;
  o.law.tol = 1e-8;
  o.spin_sign = -1;
  sweep::CellModel m = bounce_cell_model(make_bounce_cell(o));
  m.description = name;
  return m;
}

void add_geometry(report::Section& s) {
  Ball ball;
  s.add_equation("Y(θ) = sqrt(a^2 sin^2 θ + b^2 cos^2 θ)", "rugby-ball study, eq 20 (as Y^2); docs/theory.md#bounce-geometry",
                 "depth of the lowest point below the centre");
  s.add_equation("Y_{printed}(θ) = |−b [cos^2 θ + (a/b)^2 sin^2 θ]|", "rugby-ball study, experiment 3 (實驗三) 5–7 and eq 15/18",
                 "as printed: wrong, it gives a^2/b instead of a at θ = 90 deg");
  report::Figure f;
  f.title = "Depth of the lowest point Y(θ): correct vs the study's formula";
  f.x_axis.title = "θ (deg), major axis from the horizontal";
  f.y_axis.title = "Y (m)";
  report::Series ok = named("tribolab: sqrt(a² sin²θ + b² cos²θ)"), seed = named("the rugby-ball study's printed formula"),
      brute = named("brute force: lowest of 3600 points on the ellipse");
  ok.mode = seed.mode = report::Mode::Lines;
  seed.dash = report::Dash::Dash;
  seed.color = "#d62728";
  ok.color = "#1f77b4";
  brute.color = "black";
  for (int i = 0; i <= 180; ++i) {
    const double th = i / kDegPerRad, c = std::cos(th), sn = std::sin(th);
    ok.x.push_back(i);
    ok.y.push_back(support_depth(ball, th));
    seed.x.push_back(i);
    seed.y.push_back(std::abs(-ball.b * (c * c + (ball.a / ball.b) * (ball.a / ball.b) * sn * sn)));
    if (i % 10 == 0) {  // an independent check: minimise the height over points of the ellipse
      double lowest = 0;
      for (int k = 0; k < 3600; ++k) {
        const double u = 2 * std::numbers::pi * k / 3600;
        lowest = std::min(lowest, ball.a * std::cos(u) * sn + ball.b * std::sin(u) * c);
      }
      brute.x.push_back(i);
      brute.y.push_back(-lowest);
    }
  }
  f.series = {ok, seed, brute};
  f.caption = "Default ball a = 0.145 m, b = 0.095 m. At θ = 90 deg the study's formula gives a²/b = " +
              format_value(ball.a * ball.a / ball.b) + " m instead of a = " + format_value(ball.a) + " m.";
  s.add_figure(std::move(f));
}

void add_table4(report::Section& s, std::ostream& log) {
  Ball ball;
  ball.a = 0.143;  // the seed's ball length 0.286 m
  ball.b = 0.095;
  s.add_paragraph("Ball of the study's experiment 3: a = 0.143 m (length 0.286 m), b = 0.095 m, g = 9.8 m/s^2; "
                  "released at the apex H with spin ω and the table's angle as θ at the apex. The study does "
                  "not state the sense of the spin, so both are computed.");
  s.add_equation("earliest and latest contact: sqrt(2(H − a)/g) ≤ t ≤ sqrt(2(H − b)/g)", "docs/theory.md#bounce-flight",
                 "the study prints these bounds reversed (errata)");
  struct Row { double H, spin, angle, predicted, measured; };
  const Row rows[] = {{0.715, 47.60, 0.197, 0.350, 0.358}, {0.612, 40.64, -0.827, 0.335, 0.341},
                      {0.648, 33.74, -0.231, 0.356, 0.367}};
  report::Table t;
  t.caption = "Table 4: contact time from the apex (s)";
  t.header = {"H (m)", "spin (rad/s)", "angle (rad)", "study predicted", "study measured",
              "tribolab, ω < 0 (CW)", "tribolab, ω > 0", "latest possible sqrt(2(H−b)/g)"};
  log << "  table 4: H  predicted  measured  tribolab(CW)  tribolab(CCW)  latest\n";
  for (const Row& r : rows) {
    const double cw = first_contact_from_apex(ball, r.H, -r.spin, r.angle).t_contact;
    const double ccw = first_contact_from_apex(ball, r.H, r.spin, r.angle).t_contact;
    const double latest = std::sqrt(2 * (r.H - ball.b) / kDefaultG);
    t.rows.push_back({format_value(r.H), format_value(r.spin), format_value(r.angle), format_value(r.predicted, 3), format_value(r.measured, 3),
                      format_value(cw), format_value(ccw), format_value(latest)});
    log << "    " << r.H << "  " << r.predicted << "  " << r.measured << "  " << format_value(cw) << "  " << format_value(ccw)
        << "  " << format_value(latest) << '\n';
  }
  s.add_table(std::move(t));
  s.add_paragraph("Row 1 is reproduced. Rows 2 and 3 of the prediction, and all three measurements, exceed the "
                  "latest possible contact time from an apex at H: they cannot be times from the apex (errata).");
}

void add_one_contact(report::Section& s, std::ostream& log) {
  const Ball ball;
  const double angle = 135, spin = 40, speed = 4;
  const BodyState touch = impact(ball, angle, spin, speed);
  std::vector<ContactSample> h_seed, h_low;
  const FrictionModel friction;  // Coulomb, mu = 0.5
  const ContactResult seed = simulate_contact(ball, seed_law(), friction, touch, {}, &h_seed);
  const ContactResult low = simulate_contact(ball, low_damping_law(), friction, touch, {}, &h_low);
  add_contact_equations(s, seed.law);
  s.add_paragraph("A representative impact: collision angle " + format_value(angle) + " deg (θ = " + format_value(touch.theta * kDegPerRad) +
                  " deg), v_y = −" + format_value(speed) + " m/s, ω = −" + format_value(spin) + " rad/s (clockwise), v_x = 0, Coulomb "
                  "friction μ = 0.5. Solid: the study's fitted law (e = " + format_value(seed.restitution) + ", contact " +
                  format_value(1e3 * seed.contact_duration) + " ms); dashed: the same K and n with D = 6000 (e = " +
                  format_value(low.restitution) + ").");
  ContactCurve a{"the study's law (D = 60423)", h_seed, report::Dash::Solid, "#1f77b4"};
  ContactCurve b{"low damping (D = 6000)", h_low, report::Dash::Dash, "#d62728"};
  ContactPanels panels;
  panels.tangential_force = panels.penetration = panels.energy = false;
  const double g = ContactOptions{}.g;  // simulate_contact's default, as used above
  add_contact_figures(s, "Figures 45–48", ball, g, {a, b}, panels);
  ContactPanels energy;
  energy = {false, false, false, false, false, false, true};
  add_contact_figures(s, "The study's law", ball, g, {a}, energy);
  log << "  one contact at 135 deg, 40 rad/s, 4 m/s: e = " << format_value(seed.restitution) << " (the study's law), "
      << format_value(low.restitution) << " (D = 6000)\n";
}

void add_drop(report::Section& s, std::ostream& log) {
  const Ball ball;
  DropRelease rel;
  rel.height = 0.8;
  rel.theta = 30 / kDegPerRad;
  rel.omega = -45;
  DropOptions o;
  o.max_bounces = 3;
  o.sample_dt = 2e-3;
  const FrictionModel friction;
  const DropResult low = simulate_drop(ball, low_damping_law(), friction, rel, o);
  const DropResult seed = simulate_drop(ball, seed_law(), friction, rel, o);
  s.add_paragraph("Released at rest at a centre height of 0.8 m, θ = 30 deg, spinning at −45 rad/s. With the "
                  "low-damping law the ball rebounds above its release height (the study's 反跳變高, “the rebound grows higher”); with the "
                  "study's fitted law it does not.");
  report::Figure f;
  f.title = "A drop: height of the centre";
  f.x_axis.title = "t (s)";
  f.y_axis.title = "y (m)";
  report::Series rl = named("release height");
  rl.mode = report::Mode::Lines;
  rl.dash = report::Dash::Dot;
  rl.color = "black";
  double t_last = 0;
  report::Table t;
  t.caption = "Apex heights after each bounce (m)";
  t.header = {"law", "bounce 1", "bounce 2", "bounce 3", "first above release"};
  for (const auto& [name, r, color] : {std::tuple{"low damping (D = 6000)", &low, "#d62728"},
                                      std::tuple{"the study's law (D = 60423)", &seed, "#1f77b4"}}) {
    report::Series y = named(name);
    y.mode = report::Mode::Lines;
    y.color = color;
    for (const auto& p : r->trajectory) {
      y.x.push_back(p.t);
      y.y.push_back(p.state.y);
      t_last = std::max(t_last, p.t);
    }
    f.series.push_back(std::move(y));
    std::vector<std::string> row{name};
    for (std::size_t i = 0; i < 3; ++i) row.push_back(i < r->bounces.size() ? format_value(r->bounces[i].apex_height) : "—");
    row.push_back(r->first_above_release >= 0 ? "bounce " + std::to_string(r->first_above_release + 1) : "never");
    t.rows.push_back(std::move(row));
  }
  rl.x = {0.0, t_last};
  rl.y = {rel.height, rel.height};
  f.series.push_back(rl);
  f.caption = "The centre's height; the contacts are the short dips.";
  s.add_figure(std::move(f));
  s.add_table(std::move(t));
  log << "  drop from 0.8 m: first apex " << (low.bounces.empty() ? 0.0 : low.bounces[0].apex_height)
      << " m (D = 6000), " << (seed.bounces.empty() ? 0.0 : seed.bounces[0].apex_height) << " m (the study's law)\n";
}

/// A theta x spin heat map of e for one slice with the e = 1 boundary (src/app/sweep/report_sweep.hpp).
report::Figure heat_map(const std::string& title, const sweep::GridSpec& grid, const std::vector<double>& values,
                        std::size_t n_out, int e_index, std::int64_t slice, const sweep::ContourResult& contour,
                        const std::string& spin_title) {
  SweepMapStyle style;
  style.title = title;
  style.x_title = spin_title;
  return sweep_heat_map(grid, values, n_out, e_index, slice, &contour, style);
}

double max_of(const std::vector<double>& values, std::size_t n_out, int idx, std::int64_t from, std::int64_t to) {
  double m = -std::numeric_limits<double>::infinity();
  for (std::int64_t c = from; c < to; ++c) {
    const double v = values[static_cast<std::size_t>(c) * n_out + static_cast<std::size_t>(idx)];
    if (std::isfinite(v)) m = std::max(m, v);
  }
  return m;
}

void add_maps(report::Section& s, std::ostream& log) {
  const Ball ball;
  s.add_paragraph("e = −v_y,out/v_y,in over the study's collision angle 100–170 deg × spin 30–50 rad/s, "
                  "for v_y = −4 and −8 m/s (the study's figures 53, 54), computed with the contact solver in every cell "
                  "(36 × 11 cells per map; ball moving to +x with v_x = 0, clockwise spin, Coulomb μ = 0.5). "
                  "Blue: e > 1, the ball rebounds above the height it fell from. The black curve is the e = 1 "
                  "boundary traced by marching squares and refined by root finding on the solver itself "
                  "(the study's figure 56 shows the same surface against the plane z = 1).");
  sweep::GridSpec grid;
  grid.axes = {{sweep::Quantity::speed, 4, 8, 2}, {sweep::Quantity::theta_deg, 100, 170, 36},
               {sweep::Quantity::omega, 30, 50, 11}};
  grid.fixed_mu = 0.5;
  sweep::ContourOptions co;
  co.x_tol_rel = 1e-6;  // boundary to a millionth of the grid spacing: far below the pixel size
  for (const auto& [law, name] : {std::pair{seed_law(), std::string("the study's fitted law (D = 60423)")},
                                  std::pair{low_damping_law(), std::string("low damping (D = 6000)")}}) {
    const sweep::CellModel model = contact_model(law, name);
    const std::vector<double> values = sweep::evaluate_grid(grid, model);
    const sweep::ContourResult contour = sweep::trace_contour(grid, model, values, co);
    const std::size_t n_out = model.output_names.size();
    const int e = model.output_index("e");
    for (std::int64_t slice = 0; slice < 2; ++slice) {
      const double speed = slice == 0 ? 4 : 8;
      const double emax = max_of(values, n_out, e, slice * 396, (slice + 1) * 396);
      report::Figure f = heat_map("As the study's figure " + std::string(slice == 0 ? "53" : "54") + ", v_y = −" +
                                      format_value(speed) + " m/s: " + name,
                                  grid, values, n_out, e, slice, contour, "spin |ω| (rad/s), clockwise");
      const bool seeds = law.D == seed_law().D;
      // The computed description (describe_heat_map), and what it means for the study.
      if (emax < 1)
        f.caption += seeds ? " No cell reaches e = 1, so there is no boundary: the study's maps cannot come "
                             "from its fitted law as printed (errata)."
                           : " No cell reaches e = 1 at this speed with this law either.";
      s.add_figure(std::move(f));
      log << "  map v_y = -" << speed << " m/s, " << name << ": largest e = " << format_value(emax) << '\n';
    }
  }
  // Figure 55: the spin/speed ratio at v_y = -4 m/s, low damping.
  sweep::GridSpec ratio;
  ratio.axes = {{sweep::Quantity::theta_deg, 100, 170, 36}, {sweep::Quantity::ratio, 5, 15, 11}};
  ratio.fixed_speed = 4;
  ratio.fixed_mu = 0.5;
  const sweep::CellModel model = contact_model(low_damping_law(), "low damping (D = 6000)");
  const std::vector<double> values = sweep::evaluate_grid(ratio, model);
  const sweep::ContourResult contour = sweep::trace_contour(ratio, model, values, co);
  report::Figure f = heat_map("As the study's figure 55: e over spin/speed ratio, v_y = −4 m/s, low damping (D = 6000)", ratio,
                              values, model.output_names.size(), model.output_index("e"), 0, contour,
                              "|ω| / |v_y| (rad/m)");
  f.caption = "The same e over the ratio of spin to incoming speed (ω = ratio × 4 m/s). " + f.caption;
  s.add_figure(std::move(f));
}

}  // namespace

void add_bounce_case_study(report::Report& r, std::ostream& log) {
  auto& g = r.add_section("The rugby-ball study: geometry of the lowest point");
  g.add_paragraph("The rugby ball is a rigid ellipse in the plane (semi-axes a ≥ b) over the floor y = 0; θ is the "
                  "major axis from the horizontal, ω the spin, both counter-clockwise positive.");
  add_geometry(g);
  auto& t4 = r.add_section("Bounce: table 4, the first instant of contact");
  add_table4(t4, log);
  auto& c = r.add_section("Bounce: figures 45–48, one contact");
  add_one_contact(c, log);
  auto& d = r.add_section("Bounce: rebound above the drop height");
  add_drop(d, log);
  auto& m = r.add_section("Bounce: figures 53–56, phase diagrams of the rebound");
  add_maps(m, log);
}

}  // namespace tribolab::app
