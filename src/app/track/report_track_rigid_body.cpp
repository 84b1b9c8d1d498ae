#include "app/track/report_track_rigid_body.hpp"
#include "app/common/report_util.hpp"

#include "report/format.hpp"

#include <cmath>
#include <functional>
#include <numbers>

namespace tribolab::app {

namespace {

using Row = track::RigidBodyRow;

/// One series of a quantity of every row against t.
report::Series against_t(std::string name, const std::vector<Row>& rows, const std::function<double(const Row&)>& value,
                         const std::function<double(const Row&)>& error = {}) {
  report::Series s = named(std::move(name));
  for (const Row& r : rows) {
    s.x.push_back(r.t);
    s.y.push_back(value(r));
    if (error) s.y_error.push_back(error(r));
  }
  return s;
}

}  // namespace

report::Report track_rigid_body_report(const TrackRigidBodyResult& result, const std::string& source) {
  const track::RigidBody& body = result.body;
  const auto& rows = body.rows;
  const LengthCheck& len = result.length;
  const std::string ab = "'" + body.point_a + "' → '" + body.point_b + "'";
  report::Report r;
  r.title = "tribolab track rigid-body";
  r.subtitle = "Points " + ab + " of " + source;
  auto& s = r.add_section("A body from two of its points");
  s.add_equation("x_c = (x_A + x_B)/2,   y_c = (y_A + y_B)/2,   θ = atan2(y_B − y_A, x_B − x_A) (unwrapped)",
                 "docs/theory.md#track-rigid-body", "the centre is the midpoint of the two points");
  s.add_equation("θ(t) ≈ θ_0 + ω (t − t̄): ω from a least-squares line, globally and over a sliding window",
                 "docs/theory.md#track-rigid-body", "error bars: one standard error from the residual scatter");
  report::Table t;
  t.caption = "Summary";
  t.header = {"quantity", "value"};
  t.rows = {{"frames with both points", std::to_string(rows.size())},
            {"spin ω over the record (rad/s)", report::format_uncertain(body.spin.omega, body.spin.sigma_omega)},
            {"turns", report::format_value((rows.back().theta - rows.front().theta) / (2 * std::numbers::pi), 4)},
            {"A–B distance, mean ± sd (m)", report::format_uncertain(len.mean, len.sd)},
            {"A–B distance change over the record (m)", report::format_uncertain(len.drift, len.sigma_drift)}};
  s.add_table(std::move(t));
  if (result.json.contains("warnings") && !result.json["warnings"].empty()) {
    std::vector<std::string> items;
    for (const auto& w : result.json["warnings"]) items.push_back(w.get<std::string>());
    s.add_subheading("Warnings");
    s.add_list(std::move(items));
  }

  report::Figure path = make_figure("Path of the centre", "x (m)", "y (m)", 420);
  path.equal_aspect = true;
  {
    report::Series c = named("centre", report::Mode::LinesMarkers);
    for (const Row& w : rows) {
      c.x.push_back(w.xc);
      c.y.push_back(w.yc);
    }
    path.series.push_back(std::move(c));
  }
  path.caption = "The midpoint of the two points in the plane of the video (equal scales).";
  s.add_figure(std::move(path));

  report::Figure theta = make_figure("Orientation θ of " + ab, "t (s)", "θ (rad)", 340);
  theta.series.push_back(against_t("θ, unwrapped", rows, [](const Row& w) { return w.theta; }));
  if (std::isfinite(body.spin.omega)) {
    const double t0 = rows.front().t, t1 = rows.back().t;
    const auto line = [&](double tt) { return body.spin.theta_ref + body.spin.omega * (tt - body.spin.t_ref); };
    theta.series.push_back(make_line("global fit ω = " + report::format_uncertain(body.spin.omega, body.spin.sigma_omega) +
                                         " rad/s",
                                     {t0, t1}, {line(t0), line(t1)}, report::Dash::Dash));
  }
  s.add_figure(std::move(theta));

  report::Figure spin = make_figure("Spin ω against time (local fits ± 1 standard error)", "t (s)", "ω (rad/s)", 340);
  spin.series.push_back(against_t("ω local", rows, [](const Row& w) { return w.omega; },
                                  [](const Row& w) { return w.sigma_omega; }));
  spin.series.push_back(make_line("ω over the record", {rows.front().t, rows.back().t},
                                  {body.spin.omega, body.spin.omega}, report::Dash::Dash));
  s.add_figure(std::move(spin));

  report::Figure dist = make_figure("Distance A–B against time", "t (s)", "|AB| (m)", 340);
  dist.series.push_back(against_t("|AB|", rows, [](const Row& w) { return w.length; }));
  dist.series.push_back(make_line("mean", {rows.front().t, rows.back().t}, {len.mean, len.mean}, report::Dash::Dash));
  dist.caption = "A rigid body keeps this distance: a drift means a wrong or moving calibration, jumps a mislabelled mark.";
  s.add_figure(std::move(dist));
  return r;
}

}  // namespace tribolab::app
