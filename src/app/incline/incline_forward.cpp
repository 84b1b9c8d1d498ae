#include "app/common/study_citation.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"
#include "app/incline/incline_forward.hpp"

#include "app/common/output_paths.hpp"

#include "app/incline/report_incline.hpp"
#include "incline/numeric.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace tribolab::app {
namespace {

using nlohmann::json;

/// The keys predict and each member of families share: k, regime, the stop point and x_limit.
void add_prediction_keys(json& j, const incline::Prediction& pr) {
  j["k"] = json_number(pr.k);
  j["regime"] = incline::to_string(pr.regime);
  j["t_stop"] = json_number(pr.t_stop);
  j["x_stop"] = json_number(pr.x_stop);
  j["y_stop"] = json_number(pr.y_stop);
  j["x_limit"] = json_number(pr.x_limit);
}

void write_state(std::ostream& out, const incline::State& st) {
  const incline::State s{st.t + 0.0, st.x + 0.0, st.y + 0.0, st.vx + 0.0,
                         st.vy + 0.0, st.ax + 0.0, st.ay + 0.0};  // -0 -> 0
  out << io::format_number(s.t) << ',' << io::format_number(s.x) << ',' << io::format_number(s.y)
      << ',' << io::format_number(s.vx) << ',' << io::format_number(s.vy) << ','
      << io::format_number(s.ax) << ',' << io::format_number(s.ay) << '\n';
}

/// Sample times 0, dt, 2 dt, ... up to t_end (inclusive, within rounding).
std::vector<double> time_grid(double t_end, double dt) {
  const double n_real = std::floor(t_end / dt * (1 + 1e-12));
  if (n_real > 1e7) throw InputError(field("dt"), "gives more than 10^7 rows; use a larger step");
  const auto n = static_cast<std::size_t>(n_real);
  std::vector<double> t(n + 1);
  for (std::size_t i = 0; i <= n; ++i) t[i] = static_cast<double>(i) * dt;
  return t;
}

/// Evenly spaced times 0..t_end (n + 1 of them).
std::vector<double> even_times(double t_end, int n) {
  std::vector<double> t(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) t[static_cast<std::size_t>(i)] = t_end * i / n;
  return t;
}

}  // namespace

// ---- predict --------------------------------------------------------------------------

InclinePredictResult incline_predict(const InclinePredictOptions& o) {
  check_output_paths({}, {{"report", o.report}});  // before any work (app/common/output_paths.hpp)
  InclinePredictResult res;
  const incline::Parameters& p = res.parameters = incline_launch_parameters(o.launch);
  const incline::Prediction& pr = res.prediction = incline::ClosedForm(p).predict();
  const double t_end = incline::default_duration(p);
  if (std::isfinite(t_end) && t_end > 0) res.trajectory = incline::ClosedForm(p).trajectory(even_times(t_end, 400));
  if (!o.report.empty()) report::write_html(with_study_source(incline_predict_report(p, pr, res.trajectory), Study::incline), o.report, o.plotly);
  json& j = res.json;
  add_prediction_keys(j, pr);
  j["v_terminal"] = json_number(pr.v_terminal);
  j["a_x0"] = pr.a_x0;
  j["a_y0"] = pr.a_y0;
  j["a_x_final"] = pr.a_x_final;
  j["a_y_final"] = pr.a_y_final;
  j["stays_at_rest"] = pr.stays_at_rest;
  return res;
}

// ---- simulate -------------------------------------------------------------------------

InclineSimulateResult incline_simulate(const InclineSimulateOptions& o) {
  check_output_paths({}, {{"out", o.out}, {"report", o.report}});  // before any work (app/common/output_paths.hpp)
  InclineSimulateResult res;
  incline::Parameters p = incline_launch_parameters(o.launch);
  if (o.model != "A" && o.model != "B") throw InputError(field("model"), "must be A or B, got '" + o.model + "'");
  const bool model_a = o.model == "A";
  if (o.normal_accel) {
    if (!model_a) throw InputError(field("normal_accel"), "applies to " + field("model") + " A only");
    p.normal_accel = check_range(*o.normal_accel, ranges::accel, field("normal_accel"));
  }
  const std::string method = o.method ? *o.method : (model_a ? "numeric" : "analytic");
  if (method != "analytic" && method != "numeric")
    throw InputError(field("method"), "must be analytic or numeric, got '" + method + "'");
  if (model_a && method == "analytic")
    throw InputError(field("method"), "analytic is model B's closed form; model A has none (use numeric)");
  const double t_end = o.t_end ? check_range(*o.t_end, ranges::step, field("t_end")) : incline::default_duration(p);
  const double dt = o.dt ? check_range(*o.dt, ranges::step, field("dt")) : t_end / 500;
  if (!std::isfinite(t_end) || !std::isfinite(dt) || !(dt > 0))
    throw InputError(field("t_end"), "the default duration is not finite for these parameters; give " + field("t_end") + " and " + field("dt"));
  const std::vector<double> times = time_grid(t_end, dt);

  std::optional<io::AtomicFile> file;  // opened first: a bad path fails before the work
  if (!o.out.empty()) file.emplace(o.out);
  json& j = res.json;
  j["model"] = o.model;
  j["method"] = method;
  j["rows"] = times.size();
  j["t_end"] = t_end;
  j["dt"] = dt;
  if (method == "analytic") {
    const incline::ClosedForm cf(p);
    res.trajectory = cf.trajectory(times);
    const incline::Prediction pr = cf.predict();
    const bool stopped = pr.t_stop && *pr.t_stop <= t_end;
    j["t_stop"] = stopped ? json(*pr.t_stop) : json(nullptr);
    j["x_stop"] = stopped ? json(*pr.x_stop) : json(nullptr);
    j["y_stop"] = stopped ? json(*pr.y_stop) : json(nullptr);
  } else {
    incline::NumericOptions no;
    no.model = model_a ? incline::Model::A : incline::Model::B;
    incline::NumericResult r = incline::simulate(p, times, no);
    if (r.status == incline::NumericStatus::failed)
      throw SolverError("numerical integration failed: " + r.message);
    res.trajectory = std::move(r.samples);
    // As for the analytic method: a stop is reported when it happens within t-end.
    const bool stopped = r.t_stop && *r.t_stop <= t_end;
    j["t_stop"] = stopped ? json(*r.t_stop) : json(nullptr);
    j["x_stop"] = stopped ? json(*r.x_stop) : json(nullptr);
    j["y_stop"] = stopped ? json(*r.y_stop) : json(nullptr);
    j["steps"] = r.steps;
  }
  if (!o.report.empty()) {
    // Model B: the other method on the report's sample times, as a check drawn beside it.
    const std::vector<double> shown = incline_report_times(res.trajectory);
    if (!model_a && !shown.empty()) {
      if (method == "analytic") {
        const incline::NumericResult n = incline::simulate(p, shown);
        if (n.status != incline::NumericStatus::failed) {
          res.comparison = n.samples;
          res.comparison_name = "numeric (Dormand–Prince 5(4))";
        }
      } else {
        res.comparison = incline::ClosedForm(p).trajectory(shown);
        res.comparison_name = "closed form (model B)";
      }
    }
    report::write_html(with_study_source(incline_simulate_report(p, model_a, method, res.trajectory, res.comparison,
                                                                 res.comparison_name),
                                         Study::incline),
                       o.report, o.plotly);
  }
  if (file) {
    file->stream() << "t,x,y,vx,vy,ax,ay\n";
    for (const auto& st : res.trajectory) write_state(file->stream(), st);
    file->commit();
  }
  j["out"] = o.out.empty() ? json(nullptr) : json(o.out);
  res.parameters = p;
  return res;
}

// ---- families -------------------------------------------------------------------------

InclineFamiliesResult incline_families(const InclineFamiliesOptions& s) {
  check_output_paths({}, {{"out", s.out}, {"report", s.report}});  // before any work (app/common/output_paths.hpp)
  InclineFamiliesResult res;
  incline::FamilyOptions& o = res.options;
  std::string skip;
  if (s.vary == "v0") {
    o.vary = incline::FamilyParameter::v0;
    skip = field("v0");
  } else if (s.vary == "phi") {
    o.vary = incline::FamilyParameter::phi;
    skip = field("phi_deg");
  } else if (s.vary == "mu") {
    o.vary = incline::FamilyParameter::mu;
    skip = field("mu");
  } else {
    throw InputError(field("vary"), "must be v0, phi or mu, got '" + s.vary + "'");
  }
  o.base = incline_launch_parameters(s.launch, skip);
  if (s.values.empty()) throw MissingOptionError(field("values"), "is required");
  const bool phi = o.vary == incline::FamilyParameter::phi;
  for (double v : s.values) {
    if (phi) {
      if (!(v >= 0 && v < 90))
        throw InputError(field("values"), "phi must be in [0, 90) degrees, got " + io::format_number(v));
      v = to_rad(v);
    } else {
      check_range(v, o.vary == incline::FamilyParameter::v0 ? ranges::speed : ranges::friction,
                  field("values") + " (" + s.vary + ")");
    }
    o.values.push_back(v);
  }
  if (!(s.samples >= 2 && s.samples <= 1000000))
    throw InputError(field("samples"), "must be an integer in [2, 1000000], got " + std::to_string(s.samples));
  o.samples = s.samples;
  if (s.t_end) o.t_end = check_range(*s.t_end, ranges::step, field("t_end"));
  const incline::Family& f = res.family = incline::make_family(o);
  std::optional<io::AtomicFile> file;
  if (!s.out.empty()) file.emplace(s.out);
  if (!s.report.empty()) report::write_html(with_study_source(incline_families_report(o, f), Study::incline), s.report, s.plotly);
  const std::string column = phi ? "phi_deg" : s.vary;
  if (file) file->stream() << column << ",t,x,y,vx,vy,ax,ay\n";
  json members = json::array();
  for (const auto& m : f.members) {
    const double shown = phi ? to_deg(m.value) : m.value;
    if (file) {
      for (const auto& st : m.trajectory) {
        file->stream() << io::format_number(shown) << ',';
        write_state(file->stream(), st);
      }
    }
    const auto& pr = m.prediction;
    json e;
    e[column] = shown;
    add_prediction_keys(e, pr);
    e["t_end"] = m.t_end;
    const double v0 = m.parameters.v0;
    const bool stops = pr.t_stop && v0 > 0;
    e["t_stop_over_v0"] = stops ? json(*pr.t_stop / v0) : json(nullptr);
    e["x_stop_over_v0_sq"] = stops ? json(*pr.x_stop / (v0 * v0)) : json(nullptr);
    e["y_stop_over_v0_sq"] = stops ? json(*pr.y_stop / (v0 * v0)) : json(nullptr);
    e["y_stop_over_x_stop"] = stops && *pr.x_stop > 0 ? json(*pr.y_stop / *pr.x_stop) : json(nullptr);
    members.push_back(e);
  }
  if (file) file->commit();
  json& j = res.json;
  j["vary"] = s.vary;
  j["t_end"] = f.t_end;
  j["rows"] = f.members.size() * f.members.front().trajectory.size();
  j["members"] = members;
  j["warnings"] = f.warnings;
  j["out"] = s.out.empty() ? json(nullptr) : json(s.out);
  return res;
}


const ResultKeys& incline_predict_result_keys() {
  static const ResultKeys k = {
      {"k", "", "tan(phi)/mu"}, {"regime", "", "stops, terminal_speed or accelerates"},
      {"t_stop", "s", ""}, {"x_stop", "m", ""}, {"y_stop", "m", ""}, {"x_limit", "m", "lateral limit, null when unbounded"},
      {"v_terminal", "m/s", ""}, {"a_x0", "m/s^2", "at launch"}, {"a_y0", "m/s^2", "at launch"},
      {"a_x_final", "m/s^2", ""}, {"a_y_final", "m/s^2", ""}, {"stays_at_rest", "", ""},
  };
  return k;
}

const ResultKeys& incline_simulate_result_keys() {
  static const ResultKeys k = {
      {"model", "", ""}, {"method", "", ""}, {"rows", "", "samples written"}, {"t_end", "s", ""}, {"dt", "s", ""},
      {"t_stop", "s", "within t_end, else null"}, {"x_stop", "m", ""}, {"y_stop", "m", ""},
      {"steps", "", "integrator steps (numeric)"}, {"out", "", ""},
  };
  return k;
}

const ResultKeys& incline_families_result_keys() {
  static const ResultKeys k = {
      {"vary", "", ""}, {"t_end", "s", "the longest member's"}, {"rows", "", "rows written"},
      {"members.v0", "m/s", ""}, {"members.phi_deg", "deg", ""}, {"members.mu", "", ""},
      {"members.k", "", "tan(phi)/mu"}, {"members.regime", "", ""}, {"members.t_stop", "s", ""},
      {"members.x_stop", "m", ""}, {"members.y_stop", "m", ""}, {"members.x_limit", "m", ""},
      {"members.t_end", "s", ""}, {"members.t_stop_over_v0", "s^2/m", ""}, {"members.x_stop_over_v0_sq", "s^2/m", ""},
      {"members.y_stop_over_v0_sq", "s^2/m", ""}, {"members.y_stop_over_x_stop", "", ""},
      {"warnings", "", ""}, {"out", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
