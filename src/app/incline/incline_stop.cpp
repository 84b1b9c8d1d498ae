#include "app/common/study_citation.hpp"
#include "app/incline/incline_stop.hpp"

#include "app/common/output_paths.hpp"

#include "app/incline/report_incline_analysis.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

namespace tribolab::app {

InclineMuFromStopResult incline_mu_from_stop(const InclineMuFromStopOptions& s) {
  check_output_paths({}, {{"report", s.report}});  // before any work (app/common/output_paths.hpp)
  using nlohmann::json;
  auto need = [](const std::optional<double>& v, const std::string& option) {
    if (!v) throw MissingOptionError(option, "is required");
    return *v;
  };
  InclineMuFromStopResult res;
  incline::StopMeasurement& m = res.measurement;
  const double phi_deg = need(s.phi_deg, field("phi_deg"));
  if (!(phi_deg > 0 && phi_deg < 90))
    throw InputError(field("phi_deg"), "must be in (0, 90), got " + io::format_number(phi_deg));
  m.phi = to_rad(phi_deg);
  m.x_stop = check_range(need(s.x_stop, field("x_stop")), ranges::position, field("x_stop"));
  if (!(m.x_stop > 0))
    throw InputError(field("x_stop"), "must be > 0 (launch along +x); no physical root, got " + io::format_number(m.x_stop));
  m.y_stop = check_range(need(s.y_stop, field("y_stop")), ranges::position, field("y_stop"));
  if (!(m.y_stop < 0))
    throw InputError(field("y_stop"), "must be < 0 (the disc ends below the launch line); no physical root, got " +
                                     io::format_number(m.y_stop));
  const bool has_sigma = s.sigma_phi_deg || s.sigma_pos;
  if (s.sigma_phi_deg)
    m.sigma_phi = to_rad(check_range(*s.sigma_phi_deg, ranges::angle_sigma_deg, field("sigma_phi_deg")));
  if (s.sigma_pos) m.sigma_pos = check_range(*s.sigma_pos, ranges::noise, field("sigma_pos"));
  m.g = check_range(s.g, ranges::gravity, field("g"));
  const incline::MuFromStopResult& r = res.fit = incline::mu_from_stop(m);
  json& j = res.json;
  j["mu"] = r.mu;
  j["k"] = r.k;
  j["r"] = r.r;
  j["sigma_mu"] = has_sigma ? json(r.sigma_mu) : json(nullptr);
  j["v0"] = r.v0;
  j["best_phi_deg"] = nullptr;
  j["best_sigma_mu"] = nullptr;
  if (s.plate_size) {
    const double plate = check_range(*s.plate_size, ranges::distance, field("plate_size"));
    if (!(m.sigma_phi > 0 || m.sigma_pos > 0))
      throw InputError(field("plate_size"), "the advice needs " + field("sigma_phi_deg") + " or " + field("sigma_pos") + " > 0");
    res.advice = incline::best_angle(r.mu, r.v0, incline::SetupConstraint::launch_speed, m.sigma_phi,
                                     m.sigma_pos, plate, m.g);
    j["best_phi_deg"] = to_deg(res.advice->phi);
    j["best_sigma_mu"] = res.advice->sigma_mu;
  }
  if (!s.report.empty()) report::write_html(with_study_source(incline_stop_report(m, r, has_sigma, res.advice), Study::incline), s.report, s.plotly);
  return res;
}


const ResultKeys& incline_mu_from_stop_result_keys() {
  static const ResultKeys k = {
      {"mu", "", ""}, {"k", "", "tan(phi)/mu"}, {"r", "", "|x_stop / y_stop|"}, {"v0", "m/s", "launch speed"},
      {"best_phi_deg", "deg", "the angle that minimises sigma_mu"}, {"best_sigma_mu", "", "sigma_mu at that angle"},
  };
  return k;
}
}  // namespace tribolab::app
