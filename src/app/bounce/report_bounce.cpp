#include "app/bounce/report_bounce.hpp"
#include "app/common/report_util.hpp"

#include "numerics/units.hpp"
#include "report/format.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace tribolab::app {
namespace {

using bounce::ContactSample;
using report::Figure;
using report::Series;
using report::Table;



Series history_series(const ContactCurve& c, const std::string& name,
                      const std::function<double(const ContactSample&)>& fy,
                      report::Dash dash, const std::string& color) {
  Series s;
  s.name = name;
  s.mode = report::Mode::Lines;
  s.dash = dash;
  s.color = color;
  for (const ContactSample& h : c.history) {
    s.x.push_back(1e3 * h.t);
    s.y.push_back(fy(h));
  }
  return s;
}

Figure history_figure(const std::string& title, const std::string& y_title) {
  Figure f;
  f.title = title;
  f.x_axis.title = "t from first touch (ms)";
  f.y_axis.title = y_title;
  f.height_px = 340;
  return f;
}

}  // namespace

int add_contact_figures(report::Section& s, const std::string& title, const bounce::Ball& ball, double g,
                        const std::vector<ContactCurve>& curves, const ContactPanels& panels) {
  int added = 0;
  auto one = [&](bool on, const std::string& suffix, const std::string& y_title,
                 const std::function<double(const ContactSample&)>& fy) {
    if (!on) return;
    Figure f = history_figure(title + ": " + suffix, y_title);
    for (const ContactCurve& c : curves) f.series.push_back(history_series(c, c.name, fy, c.dash, c.color));
    s.add_figure(std::move(f));
    ++added;
  };
  one(panels.vy, "v_y of the centre", "v_y (m/s)", [](const ContactSample& h) { return h.state.vy; });
  one(panels.vx, "v_x of the centre", "v_x (m/s)", [](const ContactSample& h) { return h.state.vx; });
  one(panels.omega, "spin ω", "ω (rad/s), CCW positive", [](const ContactSample& h) { return h.state.omega; });
  one(panels.normal_force, "normal force N", "N (N)", [](const ContactSample& h) { return h.N; });
  one(panels.tangential_force, "tangential force f", "f (N), +x", [](const ContactSample& h) { return h.f; });
  one(panels.penetration, "penetration d", "d (mm)", [](const ContactSample& h) { return 1e3 * h.d; });
  if (panels.energy && !curves.empty() && !curves.front().history.empty()) {
    const ContactCurve& c = curves.front();
    Figure f = history_figure(title + ": energy (" + c.name + ")", "energy (J)");
    const double y0 = c.history.front().state.y;
    // Energy balance: kinetic + m g (y - y_touch) = E_kin,touch + work of N and f, with the
    // powers -N d' (N at the contact point) and f v_t integrated by the trapezoid rule.
    double work_normal = 0;
    const double ke0 = bounce::kinetic_energy(ball, c.history.front().state).total();
    Series trans = named("kinetic, translational"), rot = named("kinetic, rotational"),
        wn = named("kinetic at touch + work of N and f"),
        mech = named("kinetic + m g (y − y_touch)");
    double work_f = 0;
    for (std::size_t i = 0; i < c.history.size(); ++i) {
      const ContactSample& h = c.history[i];
      if (i > 0) {
        const ContactSample& p = c.history[i - 1];
        const double dt = h.t - p.t;
        // Power of N at the contact point: N (vy + omega X) = -N d_dot; of f: f v_t.
        work_normal += 0.5 * dt * (-h.N * h.d_dot - p.N * p.d_dot);
        work_f += 0.5 * dt * (h.f * h.v_t + p.f * p.v_t);
      }
      const auto ke = bounce::kinetic_energy(ball, h.state);
      const double t_ms = 1e3 * h.t;
      for (Series* se : {&trans, &rot, &wn, &mech}) se->x.push_back(t_ms);
      trans.y.push_back(ke.translational_x + ke.translational_y);
      rot.y.push_back(ke.rotational);
      wn.y.push_back(ke0 + work_normal + work_f);
      mech.y.push_back(ke.total() + ball.mass * g * (h.state.y - y0));
    }
    for (Series* se : {&trans, &rot, &wn, &mech}) {
      se->mode = report::Mode::Lines;
      f.series.push_back(std::move(*se));
    }
    f.caption = "The two upper curves agree up to the trapezoid rule's error: the energy the "
                "contact forces take is the work of N and f.";
    s.add_figure(std::move(f));
    ++added;
  }
  return added;
}

void add_contact_equations(report::Section& s, const bounce::NormalLaw& law) {
  s.add_equation("m x'' = f,   m y'' = N − m g,   I θ'' = X N + Y f", "docs/theory.md#bounce-contact",
                 "rigid ellipse; support point at (X, −Y) from the centre");
  s.add_equation("Y(θ) = sqrt(a^2 sin^2 θ + b^2 cos^2 θ),   X = −dY/dθ", "rugby-ball study, eq 20 (Y^2); docs/theory.md#bounce-geometry",
                 "the study's eqs 15/18 print a wrong Y (see the errata)");
  s.add_equation("d = Y(θ) − y,   d' = −(v_y + ω X),   v_t = v_x + ω Y", "docs/theory.md#bounce-geometry");
  if (law.linear) {
    s.add_equation("N = max(0, K d + D d')", "docs/theory.md#bounce-normal-laws",
                   "K = " + report::format_value(law.K) + " N/m, D = " + report::format_value(law.D) + " N s/m");
  } else {
    s.add_equation("N = max(0, K d^n (1 + (D/K) d'))", "rugby-ball study, research methods 6 (研究方法 六) (Hunt & Crossley 1975)",
                   "K = " + report::format_value(law.K) + " N/m^n, n = " + report::format_value(law.n) + ", D = " + report::format_value(law.D) + " N s/m^(n+1)");
  }
  s.add_equation("|f| ≤ μ N (Coulomb: stick when |f| < μ N, else f = −μ N sign v_t)",
                 "docs/theory.md#bounce-friction");
}

report::Table ball_table(const bounce::Ball& ball) {
  Table t;
  t.caption = "Ball";
  t.header = {"quantity", "value"};
  t.rows = {{"a (semi-major axis), m", report::format_value(ball.a)},
            {"b (semi-minor axis), m", report::format_value(ball.b)},
            {"mass, kg", report::format_value(ball.mass)},
            {"I (about the centre), kg m^2", report::format_value(ball.inertia)}};
  return t;
}

report::Report bounce_simulate_report(const bounce::Ball& ball, const bounce::FrictionModel& friction,
                                      double g, const bounce::ContactResult& r,
                                      const std::vector<bounce::ContactSample>& history,
                                      std::size_t contacts) {
  report::Report rep;
  rep.title = "tribolab bounce simulate";
  rep.subtitle = "One impact of a spinning ellipse on the floor (rugby-ball study, experiment 4)";
  auto& s = rep.add_section("Contact");
  if (contacts > 1) {
    s.add_paragraph("The ball touched the floor " + std::to_string(contacts) +
                    " times before flying free to its apex: the values below are those of the whole impact, "
                    "from the first touch to the last separation (docs/theory.md#bounce-contact); the time "
                    "histories show the contacts, not the flights between them.");
  }
  s.add_table(ball_table(ball));
  add_contact_equations(s, r.law);
  s.add_paragraph(std::string("Friction: ") + std::string(bounce::to_string(friction.kind)) +
                  ", μ = " + report::format_value(friction.mu) + ". Status: " + std::string(r.message) + ".");
  Table io;
  io.caption = "In and out";
  io.header = {"quantity", "at first touch", "at separation"};
  io.rows = {{"θ (deg)", report::format_value(r.in.theta * kDegPerRad), report::format_value(r.out.theta * kDegPerRad)},
             {"v_x (m/s)", report::format_value(r.in.vx), report::format_value(r.out.vx)},
             {"v_y (m/s)", report::format_value(r.in.vy), report::format_value(r.out.vy)},
             {"ω (rad/s)", report::format_value(r.in.omega), report::format_value(r.out.omega)},
             {"kinetic energy (J)", report::format_value(r.energy_in.total()), report::format_value(r.energy_out.total())}};
  s.add_table(std::move(io));
  Table key;
  key.caption = "Key numbers";
  key.header = {"quantity", "value"};
  key.rows = {{"e = −v_y,out / v_y,in", report::format_value(r.restitution)},
              {"contact duration (ms)", report::format_value(1e3 * r.contact_duration)},
              {"peak normal force (N)", report::format_value(r.peak_force)},
              {"max penetration (mm)", report::format_value(1e3 * r.max_penetration)},
              {"energy dissipated by normal damping (J)", report::format_value(r.dissipated_normal)},
              {"energy dissipated by friction (J)", report::format_value(r.dissipated_friction)},
              {"energy balance residual (J)", report::format_value(r.energy_residual, 2)}};
  s.add_table(std::move(key));
  Table phases;
  phases.caption = "Stick/slip phases";
  phases.header = {"phase", "kind", "from (ms)", "to (ms)"};
  const std::size_t n = std::min(r.n_phases, bounce::kMaxStoredPhases);
  for (std::size_t i = 0; i < n; ++i) {
    phases.rows.push_back({std::to_string(i + 1), std::string(bounce::to_string(r.phases[i].kind)),
                           report::format_value(1e3 * r.phases[i].t_start), report::format_value(1e3 * r.phases[i].t_end)});
  }
  if (r.n_phases > n) phases.caption += " (first " + std::to_string(n) + " of " + std::to_string(r.n_phases) + ")";
  s.add_table(std::move(phases));
  add_contact_figures(s, "Contact", ball, g, {{"simulation", history, report::Dash::Solid, ""}});
  return rep;
}

report::Report bounce_drop_report(const bounce::Ball& ball, const bounce::FrictionModel& friction,
                                  const bounce::DropRelease& release, const bounce::DropResult& r) {
  report::Report rep;
  rep.title = "tribolab bounce drop";
  rep.subtitle = "Release, flight and bounces (rugby-ball study; rebound above the release height)";
  auto& s = rep.add_section("Drop");
  s.add_table(ball_table(ball));
  if (!r.bounces.empty()) add_contact_equations(s, r.bounces.front().contact.law);
  s.add_paragraph("Release: centre height " + report::format_value(release.height) + " m, θ = " + report::format_value(release.theta * kDegPerRad) +
                  " deg, ω = " + report::format_value(release.omega) + " rad/s, v_x = " + report::format_value(release.vx) + " m/s, v_y = " +
                  report::format_value(release.vy) + " m/s. Friction: " + std::string(bounce::to_string(friction.kind)) +
                  ", μ = " + report::format_value(friction.mu) + ". Status: " + std::string(bounce::to_string(r.status)) + ".");
  Table t;
  t.caption = "Bounces";
  t.header = {"bounce", "t_touch (s)", "collision angle (deg)", "v_y,in (m/s)", "ω_in (rad/s)", "e",
              "apex after (m)", "above release?"};
  for (std::size_t i = 0; i < r.bounces.size(); ++i) {
    const auto& b = r.bounces[i];
    t.rows.push_back({std::to_string(i + 1), report::format_value(b.t_touch), report::format_value(b.collision_angle_deg), report::format_value(b.touch.vy),
                      report::format_value(b.touch.omega), report::format_value(b.contact.restitution), report::format_value(b.apex_height),
                      b.above_release ? "yes" : "no"});
  }
  s.add_table(std::move(t));
  Figure f;
  f.title = "Height of the centre";
  f.x_axis.title = "t (s)";
  f.y_axis.title = "y (m)";
  Series y = named("centre"), contact = named("in contact"), rel = named("release apex"), apex = named("apexes");
  y.mode = report::Mode::Lines;
  contact.color = "#d62728";
  for (const auto& p : r.trajectory) {
    y.x.push_back(p.t);
    y.y.push_back(p.state.y);
    if (p.in_contact) {
      contact.x.push_back(p.t);
      contact.y.push_back(p.state.y);
    }
  }
  const double t_last = r.trajectory.empty() ? 1.0 : r.trajectory.back().t;
  rel.x = {0.0, t_last};
  rel.y = {r.release_apex, r.release_apex};
  rel.mode = report::Mode::Lines;
  rel.dash = report::Dash::Dash;
  rel.color = "black";
  for (const auto& b : r.bounces) {
    apex.x.push_back(b.t_apex);
    apex.y.push_back(b.apex_height);
  }
  f.series = {y, contact, rel, apex};
  f.caption = "Sampled flights; contacts marked in red; dashed: the release apex height.";
  s.add_figure(f);
  Figure th;
  th.title = "Orientation θ";
  th.x_axis.title = "t (s)";
  th.y_axis.title = "θ (deg)";
  Series ths = named("θ");
  ths.mode = report::Mode::Lines;
  for (const auto& p : r.trajectory) {
    ths.x.push_back(p.t);
    ths.y.push_back(p.state.theta * kDegPerRad);
  }
  th.series = {ths};
  th.height_px = 300;
  s.add_figure(th);
  return rep;
}

report::Report bounce_contact_time_report(const bounce::Ball& ball, const bounce::BodyState& apex, int direction,
                                          const bounce::FlightResult& r, const std::vector<FlightSample>& samples) {
  report::Report rep;
  rep.title = "tribolab bounce contact-time";
  rep.subtitle = "First contact after release from an apex (rugby-ball study, experiment 3, table 4)";
  auto& s = rep.add_section("First contact");
  s.add_table(ball_table(ball));
  s.add_equation("y(t) = H − g t^2/2,   θ(t) = θ_0 + ω t", "rugby-ball study, experiment 3 (實驗三)");
  s.add_equation("gap(t) = y(t) − Y(θ(t)),   Y(θ) = sqrt(a^2 sin^2 θ + b^2 cos^2 θ)",
                 "rugby-ball study, eq 20; docs/theory.md#bounce-flight", "first root of the gap");
  s.add_equation("sqrt(2(H − a)/g) ≤ t_contact ≤ sqrt(2(H − b)/g)", "docs/theory.md#bounce-flight",
                 "the study prints these bounds reversed (see the errata)");
  Table t;
  t.caption = "Result";
  t.header = {"quantity", "value"};
  t.rows = {{"H (m)", report::format_value(apex.y)},
            {"ω (rad/s)", report::format_value(apex.omega)},
            {"θ_0 (deg)", report::format_value(apex.theta * kDegPerRad)},
            {"t_contact (s)", report::format_value(r.t_contact, 5)},
            {"earliest / latest possible (s)", report::format_value(r.t_min) + " / " + report::format_value(r.t_max)},
            {"θ at contact (deg)", report::format_value(bounce::wrap_angle(r.state.theta) * kDegPerRad)},
            {"collision angle (deg)", report::format_value(bounce::collision_angle_deg(ball, r.state.theta, direction))},
            {"grazing", r.grazing ? "yes" : "no"}};
  s.add_table(std::move(t));
  Figure gap;
  gap.title = "Gap between the lowest point and the floor";
  gap.x_axis.title = "t from release (s)";
  gap.y_axis.title = "gap (mm)";
  Figure ori;
  ori.title = "Orientation θ";
  ori.x_axis.title = "t from release (s)";
  ori.y_axis.title = "θ (deg), wrapped to (−180, 180]";
  Series gs = named("y − Y(θ)"), os = named("θ"), mark = named("first contact");
  gs.mode = os.mode = report::Mode::Lines;
  for (const FlightSample& p : samples) {
    gs.x.push_back(p.t);
    gs.y.push_back(1e3 * p.gap);
    os.x.push_back(p.t);
    os.y.push_back(to_deg(bounce::wrap_angle(p.state.theta)));
  }
  mark.x = {r.t_contact};
  mark.y = {0.0};
  mark.color = "#d62728";
  gap.series = {gs, mark};
  ori.series = {os};
  ori.height_px = 300;
  s.add_figure(gap);
  s.add_figure(ori);
  return rep;
}

}  // namespace tribolab::app
