#include "app/track/report_track.hpp"
#include "app/common/report_util.hpp"

#include "report/format.hpp"

#include <cmath>
#include <functional>
#include <limits>

namespace tribolab::app {

report::Report track_kinematics_report(const track::Kinematics& k, const track::KinematicsOptions& options,
                                       const std::string& source,
                                       const std::vector<track::SegmentAcceleration>& segment_fits,
                                       const std::vector<std::string>& warnings) {
  using Row = track::KinematicsRow;
  const bool savgol = k.method == track::DerivativeMethod::savgol;
  report::Report r;
  r.title = "tribolab track kinematics";
  r.subtitle = "Track '" + k.track + "' of " + source + ", method " + track::to_string(k.method);
  auto& s = r.add_section("Kinematics of '" + k.track + "'");
  if (savgol) {
    s.add_equation("v_i = p'(t_i),   a_i = p''(t_i),   p = least-squares polynomial of degree " +
                       std::to_string(options.order) + " through the " + std::to_string(options.window) +
                       " nearest points of the same flight",
                   "docs/theory.md#kinematics (Savitzky & Golay 1964, Anal. Chem. 36)",
                   "error bars: one standard error, from the pooled residual scatter of the local fits");
  } else {
    s.add_equation("v_i = (x_{i+1} − x_{i−1})/(t_{i+1} − t_{i−1})", "docs/theory.md#kinematics",
                   "Tracker's own finite differences");
    s.add_equation("a_i = (2x_{i−2} − x_{i−1} − 2x_i − x_{i+1} + 2x_{i+2})/(7 Δt^2)", "docs/theory.md#kinematics",
                   "Tracker's 5-point acceleration");
  }
  report::Table info;
  info.caption = "Summary";
  info.header = {"quantity", "value"};
  info.rows = {{"points", std::to_string(k.rows.size())},
               {"flight segments", std::to_string(k.segments)},
               {"impacts detected", std::to_string(k.impacts.size())},
               {"position noise x, y (m)", report::format_value(k.noise_x, 3) + ", " + report::format_value(k.noise_y, 3)}};
  if (savgol)
    info.rows.push_back({"residual σ of the local fits x, y (m)",
                         report::format_value(k.residual_sigma_x, 3) + ", " + report::format_value(k.residual_sigma_y, 3)});
  s.add_table(std::move(info));
  if (!k.impacts.empty()) {
    report::Table im;
    im.caption = "Impacts (derivatives are not taken across them)";
    im.header = {"#", "frame", "t (s)", "Δv_x (m/s)", "Δv_y (m/s)", "significance (σ)"};
    int i = 0;
    for (const auto& m : k.impacts)
      im.rows.push_back({std::to_string(++i), std::to_string(m.frame), report::format_value(m.t, 5),
                         report::format_value(m.dvx, 3), report::format_value(m.dvy, 3),
                         report::format_value(m.significance, 3)});
    s.add_table(std::move(im));
  }
  if (!segment_fits.empty()) {
    report::Table ft;
    ft.caption = "One constant acceleration fitted to each segment; a free flight is held against g "
                 "(docs/theory.md#free-flight-check)";
    ft.header = {"segment", "frames", "a_x (m/s^2)", "a_y (m/s^2)", "|a| (m/s^2)", "tilt from −y (deg)", "free flight?",
                 "falls at g?"};
    int i = 0;
    for (const auto& a : segment_fits)
      ft.rows.push_back({std::to_string(++i), std::to_string(a.frame_first) + "–" + std::to_string(a.frame_last),
                         report::format_uncertain(a.ax, a.sigma_ax), report::format_uncertain(a.ay, a.sigma_ay),
                         report::format_uncertain(a.magnitude, a.sigma_magnitude),
                         report::format_uncertain(a.tilt_deg, a.sigma_tilt_deg),
                         a.checked() ? "yes" : std::string("no: ") + track::to_string(a.shape),
                         a.checked() ? (a.plausible() ? "yes" : "no (see the warnings)") : "not checked"});
    s.add_table(std::move(ft));
  }
  if (!warnings.empty()) {
    s.add_subheading("Warnings");
    s.add_list(std::vector<std::string>(warnings));
  }
  struct Panel {
    const char* name;
    const char* y_title;
    std::function<double(const Row&)> value, sigma;
  };
  const auto none = [](const Row&) { return std::numeric_limits<double>::quiet_NaN(); };
  const Panel panels[] = {
      {"x–t", "x (m)", [](const Row& w) { return w.x; }, none},
      {"y–t", "y (m)", [](const Row& w) { return w.y; }, none},
      {"v_x–t", "v_x (m/s)", [](const Row& w) { return w.vx; }, [](const Row& w) { return w.sigma_vx; }},
      {"v_y–t", "v_y (m/s)", [](const Row& w) { return w.vy; }, [](const Row& w) { return w.sigma_vy; }},
      {"a_x–t", "a_x (m/s^2)", [](const Row& w) { return w.ax; }, [](const Row& w) { return w.sigma_ax; }},
      {"a_y–t", "a_y (m/s^2)", [](const Row& w) { return w.ay; }, [](const Row& w) { return w.sigma_ay; }},
  };
  for (const Panel& p : panels) {
    report::Figure f;
    f.title = k.track + ": " + p.name;
    f.x_axis.title = "t (s)";
    f.y_axis.title = p.y_title;
    f.height_px = 340;
    report::Series d = named(savgol ? "savgol ± 1 standard error" : "Tracker's differences");
    d.mode = report::Mode::Markers;
    bool any_sigma = false;
    for (const Row& w : k.rows) {
      d.x.push_back(w.t);
      d.y.push_back(p.value(w));
      const double sg = p.sigma(w);
      d.y_error.push_back(sg);
      any_sigma = any_sigma || std::isfinite(sg);
    }
    if (!any_sigma) d.y_error.clear();
    f.series.push_back(std::move(d));
    if (!k.impacts.empty()) {
      // Vertical lines at the impacts, spanning the data's range.
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Row& w : k.rows) {
        const double v = p.value(w);
        if (std::isfinite(v)) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      }
      if (std::isfinite(lo)) {
        report::Series m = named("impacts");
        m.mode = report::Mode::Lines;
        m.dash = report::Dash::Dot;
        m.color = "#d62728";
        for (const auto& im : k.impacts) {
          if (!m.x.empty()) {
            m.x.push_back(std::numeric_limits<double>::quiet_NaN());
            m.y.push_back(std::numeric_limits<double>::quiet_NaN());
          }
          m.x.insert(m.x.end(), {im.t, im.t});
          m.y.insert(m.y.end(), {lo, hi});
        }
        f.series.push_back(std::move(m));
      }
    }
    s.add_figure(std::move(f));
  }
  return r;
}

}  // namespace tribolab::app
