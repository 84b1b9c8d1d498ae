// `tribolab incline ...`: predict, simulate, mu-from-stop, families (SPEC section 5,
// and the tracked-run analyses of incline_analysis_cmd.cpp;
// docs/cli.md#incline). Options are parsed as text and converted with io::parse_double so
// that every error names its option; the library does the physics.
#include "app.hpp"
#include "incline_analysis_cmd.hpp"
#include "app/report_incline.hpp"
#include "app/report_incline_analysis.hpp"
#include "report_option.hpp"

#include "incline/closed_form.hpp"
#include "incline/families.hpp"
#include "incline/inverse.hpp"
#include "incline/numeric.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using incline::Parameters;
using nlohmann::json;

json opt(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }
json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

/// Launch parameters given as text, shared by predict, simulate and families.
struct LaunchText {
  std::string mu, phi_deg, v0, g = "9.8", mu_static;
};

void add_launch_options(CLI::App* cmd, LaunchText& t, bool required) {
  auto* mu = cmd->add_option("--mu", t.mu, "Kinetic friction coefficient (>= 0)");
  auto* phi = cmd->add_option("--phi-deg", t.phi_deg, "Incline angle, degrees, in [0, 90)");
  auto* v0 = cmd->add_option("--v0", t.v0, "Launch speed along +x, m/s (>= 0)");
  if (required) {
    mu->required();
    phi->required();
    v0->required();
  }
  cmd->add_option("--g", t.g, "Gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--mu-static", t.mu_static,
                  "Static friction coefficient deciding whether a disc at rest stays (default: --mu)");
}

/// Shows NUM, FILE, LIST or the choices instead of CLI11's TEXT in --help.
void name_option_types(CLI::App* cmd) {
  for (CLI::Option* o : cmd->get_options()) {
    if (o->get_lnames().empty()) continue;
    const std::string n = o->get_lnames().front();
    if (n == "help" || n == "json") continue;  // flags
    if (n == "out") o->type_name("FILE");
    else if (n == "values") o->type_name("LIST");
    else if (n == "model") o->type_name("A|B");
    else if (n == "method") o->type_name("analytic|numeric");
    else if (n == "vary") o->type_name("v0|phi|mu");
    else o->type_name("NUM");
  }
}

double number(const std::string& text, const std::string& option) {
  return io::parse_double(text, option);
}

/// Converts the launch options; `skip` names one that may be absent (the varied one).
Parameters parse_launch(const LaunchText& t, const std::string& skip = "") {
  Parameters p;
  auto need = [&](const std::string& text, const std::string& option, double fallback) {
    if (text.empty()) {
      if (option == skip) return fallback;
      throw InputError(option, "is required");
    }
    return number(text, option);
  };
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  p.mu = check_range(need(t.mu, "--mu", 0.0), ranges::friction, "--mu");
  const double phi_deg = need(t.phi_deg, "--phi-deg", 0.0);
  if (!(phi_deg >= 0 && phi_deg < 90))
    throw InputError("--phi-deg", "must be in [0, 90), got " + t.phi_deg);
  p.phi = incline::deg_to_rad(phi_deg);
  p.v0 = check_range(need(t.v0, "--v0", 0.0), ranges::speed, "--v0");
  p.g = check_range(number(t.g, "--g"), ranges::gravity, "--g");
  if (!t.mu_static.empty())
    p.mu_static = check_range(number(t.mu_static, "--mu-static"), ranges::friction, "--mu-static");
  p.check();
  return p;
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
  if (n_real > 1e7) throw InputError("--dt", "gives more than 10^7 rows; use a larger step");
  const auto n = static_cast<std::size_t>(n_real);
  std::vector<double> t(n + 1);
  for (std::size_t i = 0; i <= n; ++i) t[i] = static_cast<double>(i) * dt;
  return t;
}

// ---- predict -------------------------------------------------------------------------

void add_predict(CLI::App* area) {
  auto* cmd = area->add_subcommand("predict", "Closed-form prediction of a launch (model B)");
  auto t = std::make_shared<LaunchText>();
  auto as_json = std::make_shared<bool>(false);
  auto report_path = std::make_shared<std::string>();
  add_launch_options(cmd, *t, true);
  add_json_flag(*cmd, *as_json);
  name_option_types(cmd);
  add_report_option(*cmd, *report_path);
  cmd->callback([t, as_json, report_path] {
    const Parameters p = parse_launch(*t);
    const incline::Prediction pr = incline::ClosedForm(p).predict();
    write_report_if_requested(*report_path, [&] { return incline_predict_report(p, pr); });
    json j;
    j["k"] = finite_or_null(pr.k);
    j["regime"] = incline::to_string(pr.regime);
    j["t_stop"] = opt(pr.t_stop);
    j["x_stop"] = opt(pr.x_stop);
    j["y_stop"] = opt(pr.y_stop);
    j["v_terminal"] = opt(pr.v_terminal);
    j["x_limit"] = opt(pr.x_limit);
    j["a_x0"] = pr.a_x0;
    j["a_y0"] = pr.a_y0;
    j["a_x_final"] = pr.a_x_final;
    j["a_y_final"] = pr.a_y_final;
    j["stays_at_rest"] = pr.stays_at_rest;
    print_result(j, *as_json);
  });
}

// ---- simulate ------------------------------------------------------------------------

struct SimulateText {
  LaunchText launch;
  std::string model = "B", method, normal_accel, dt, t_end, out, report;
  bool json = false;
};

void add_simulate(CLI::App* area) {
  auto* cmd = area->add_subcommand("simulate", "Trajectory of a launch as CSV (t,x,y,vx,vy,ax,ay)");
  auto s = std::make_shared<SimulateText>();
  add_launch_options(cmd, s->launch, true);
  cmd->add_option("--model", s->model, "A (normal friction component) or B (default)");
  cmd->add_option("--normal-accel", s->normal_accel,
                  "Model A: normal friction / mass, m/s^2, positive left of the velocity (default 0)");
  cmd->add_option("--method", s->method,
                  "analytic (closed form, model B only) or numeric; default analytic for B, numeric for A");
  cmd->add_option("--dt", s->dt, "Sample interval, s (default t-end/500)");
  cmd->add_option("--t-end", s->t_end,
                  "Duration, s (default 1.25 t_stop if it stops, else 2 v0/(g mu cos phi), else 1)");
  cmd->add_option("--out", s->out, "Output CSV file")->required();
  add_json_flag(*cmd, s->json);
  name_option_types(cmd);
  add_report_option(*cmd, s->report);
  cmd->callback([s] {
    Parameters p = parse_launch(s->launch);
    if (s->model != "A" && s->model != "B")
      throw InputError("--model", "must be A or B, got '" + s->model + "'");
    const bool model_a = s->model == "A";
    if (!s->normal_accel.empty()) {
      if (!model_a) throw InputError("--normal-accel", "applies to --model A only");
      p.normal_accel = check_range(number(s->normal_accel, "--normal-accel"), ranges::accel, "--normal-accel");
    }
    std::string method = s->method.empty() ? (model_a ? "numeric" : "analytic") : s->method;
    if (method != "analytic" && method != "numeric")
      throw InputError("--method", "must be analytic or numeric, got '" + method + "'");
    if (model_a && method == "analytic")
      throw InputError("--method", "analytic is model B's closed form; model A has none (use numeric)");
    double t_end = incline::default_duration(p);
    if (!s->t_end.empty()) {
      t_end = check_range(number(s->t_end, "--t-end"), ranges::step, "--t-end");
    }
    double dt = t_end / 500;
    if (!s->dt.empty()) dt = check_range(number(s->dt, "--dt"), ranges::step, "--dt");
    if (!std::isfinite(t_end) || !std::isfinite(dt) || !(dt > 0))
      throw InputError("--t-end", "the default duration is not finite for these parameters; give --t-end and --dt");
    const std::vector<double> times = time_grid(t_end, dt);

    io::AtomicFile file(s->out);
    json j;
    j["model"] = s->model;
    j["method"] = method;
    j["rows"] = times.size();
    j["t_end"] = t_end;
    j["dt"] = dt;
    std::vector<incline::State> states;
    if (method == "analytic") {
      const incline::ClosedForm cf(p);
      states = cf.trajectory(times);
      const incline::Prediction pr = cf.predict();
      j["t_stop"] = pr.t_stop && *pr.t_stop <= t_end ? json(*pr.t_stop) : json(nullptr);
      j["x_stop"] = pr.t_stop && *pr.t_stop <= t_end ? json(*pr.x_stop) : json(nullptr);
      j["y_stop"] = pr.t_stop && *pr.t_stop <= t_end ? json(*pr.y_stop) : json(nullptr);
    } else {
      incline::NumericOptions o;
      o.model = model_a ? incline::Model::A : incline::Model::B;
      const incline::NumericResult r = incline::simulate(p, times, o);
      if (r.status == incline::NumericStatus::failed)
        throw SolverError("numerical integration failed: " + r.message);
      states = r.samples;
      // As for the analytic method: a stop is reported when it happens within t-end.
      const bool stopped = r.t_stop && *r.t_stop <= t_end;
      j["t_stop"] = stopped ? json(*r.t_stop) : json(nullptr);
      j["x_stop"] = stopped ? json(*r.x_stop) : json(nullptr);
      j["y_stop"] = stopped ? json(*r.y_stop) : json(nullptr);
      j["steps"] = r.steps;
    }
    write_report_if_requested(s->report, [&] { return incline_simulate_report(p, model_a, method, states); });
    file.stream() << "t,x,y,vx,vy,ax,ay\n";
    for (const auto& st : states) write_state(file.stream(), st);
    file.commit();
    j["out"] = s->out;
    print_result(j, s->json);
  });
}

// ---- mu-from-stop --------------------------------------------------------------------

struct MuFromStopText {
  std::string phi_deg, x_stop, y_stop, sigma_phi_deg, sigma_pos, g = "9.8", plate_size, report;
  bool json = false;
};

void add_mu_from_stop(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "mu-from-stop", "Friction coefficient from the stopping point alone (seed 000, eq 十A)");
  auto s = std::make_shared<MuFromStopText>();
  cmd->add_option("--phi-deg", s->phi_deg, "Incline angle, degrees, in (0, 90)")->required();
  cmd->add_option("--x-stop", s->x_stop, "Stop position across the slope, m (> 0)")->required();
  cmd->add_option("--y-stop", s->y_stop, "Stop position up the slope, m (< 0)")->required();
  cmd->add_option("--sigma-phi-deg", s->sigma_phi_deg, "Uncertainty of the angle, degrees");
  cmd->add_option("--sigma-pos", s->sigma_pos, "Uncertainty of x-stop and of y-stop, m");
  cmd->add_option("--g", s->g, "Gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--plate-size", s->plate_size,
                  "Largest usable stop distance, m: enables the best-angle advice");
  add_json_flag(*cmd, s->json);
  name_option_types(cmd);
  add_report_option(*cmd, s->report);
  cmd->callback([s] {
    incline::StopMeasurement m;
    const double phi_deg = number(s->phi_deg, "--phi-deg");
    if (!(phi_deg > 0 && phi_deg < 90))
      throw InputError("--phi-deg", "must be in (0, 90), got " + s->phi_deg);
    m.phi = incline::deg_to_rad(phi_deg);
    m.x_stop = check_range(number(s->x_stop, "--x-stop"), ranges::position, "--x-stop");
    if (!(m.x_stop > 0))
      throw InputError("--x-stop", "must be > 0 (launch along +x); no physical root, got " + s->x_stop);
    m.y_stop = check_range(number(s->y_stop, "--y-stop"), ranges::position, "--y-stop");
    if (!(m.y_stop < 0))
      throw InputError("--y-stop", "must be < 0 (the disc ends below the launch line); no physical root, got " + s->y_stop);
    const bool has_sigma = !s->sigma_phi_deg.empty() || !s->sigma_pos.empty();
    if (!s->sigma_phi_deg.empty()) {
      const double v = check_range(number(s->sigma_phi_deg, "--sigma-phi-deg"), ranges::angle_sigma_deg,
                                   "--sigma-phi-deg");
      m.sigma_phi = incline::deg_to_rad(v);
    }
    if (!s->sigma_pos.empty()) {
      m.sigma_pos = check_range(number(s->sigma_pos, "--sigma-pos"), ranges::noise, "--sigma-pos");
    }
    m.g = check_range(number(s->g, "--g"), ranges::gravity, "--g");
    const incline::MuFromStopResult r = incline::mu_from_stop(m);
    json j;
    j["mu"] = r.mu;
    j["k"] = r.k;
    j["r"] = r.r;
    j["sigma_mu"] = has_sigma ? json(r.sigma_mu) : json(nullptr);
    j["v0"] = r.v0;
    j["best_phi_deg"] = nullptr;
    j["best_sigma_mu"] = nullptr;
    std::optional<incline::AngleAdvice> advice;
    if (!s->plate_size.empty()) {
      const double plate = check_range(number(s->plate_size, "--plate-size"), ranges::distance, "--plate-size");
      if (!(m.sigma_phi > 0 || m.sigma_pos > 0))
        throw InputError("--plate-size", "the advice needs --sigma-phi-deg or --sigma-pos > 0");
      const incline::AngleAdvice a = incline::best_angle(
          r.mu, r.v0, incline::SetupConstraint::launch_speed, m.sigma_phi, m.sigma_pos, plate, m.g);
      j["best_phi_deg"] = incline::rad_to_deg(a.phi);
      j["best_sigma_mu"] = a.sigma_mu;
      advice = a;
    }
    write_report_if_requested(s->report, [&] { return incline_stop_report(m, r, has_sigma, advice); });
    print_result(j, s->json);
  });
}

// ---- families ------------------------------------------------------------------------

struct FamiliesText {
  LaunchText launch;
  std::string vary, values, samples = "500", t_end, out, report;
  bool json = false;
};

void add_families(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "families", "Closed-form curves for several values of v0, phi or mu (seed figures 五-七)");
  auto s = std::make_shared<FamiliesText>();
  add_launch_options(cmd, s->launch, false);
  cmd->add_option("--vary", s->vary, "Parameter to vary: v0, phi or mu")->required();
  cmd->add_option("--values", s->values,
                  "Comma-separated values (m/s for v0, degrees for phi)")->required();
  cmd->add_option("--samples", s->samples, "Samples per curve (default 500)");
  cmd->add_option("--t-end", s->t_end, "Duration of every curve, s (default: each member its own, 1.25 t_stop or 2 v0/alpha)");
  cmd->add_option("--out", s->out, "Output CSV file")->required();
  add_json_flag(*cmd, s->json);
  name_option_types(cmd);
  add_report_option(*cmd, s->report);
  cmd->callback([s] {
    incline::FamilyOptions o;
    std::string skip;
    if (s->vary == "v0") {
      o.vary = incline::FamilyParameter::v0;
      skip = "--v0";
    } else if (s->vary == "phi") {
      o.vary = incline::FamilyParameter::phi;
      skip = "--phi-deg";
    } else if (s->vary == "mu") {
      o.vary = incline::FamilyParameter::mu;
      skip = "--mu";
    } else {
      throw InputError("--vary", "must be v0, phi or mu, got '" + s->vary + "'");
    }
    o.base = parse_launch(s->launch, skip);
    for (const std::string& field : io::split(s->values, ',')) {
      double v = number(field, "--values");
      if (o.vary == incline::FamilyParameter::phi) {
        if (!(v >= 0 && v < 90)) throw InputError("--values", "phi must be in [0, 90) degrees, got " + field);
        v = incline::deg_to_rad(v);
      } else {
        check_range(v, o.vary == incline::FamilyParameter::v0 ? ranges::speed : ranges::friction,
                    "--values (" + s->vary + ")");
      }
      o.values.push_back(v);
    }
    const double samples = number(s->samples, "--samples");
    if (!(samples >= 2 && samples <= 1e6 && samples == std::floor(samples)))
      throw InputError("--samples", "must be an integer in [2, 1000000], got " + s->samples);
    o.samples = static_cast<int>(samples);
    if (!s->t_end.empty()) {
      o.t_end = check_range(number(s->t_end, "--t-end"), ranges::step, "--t-end");
    }
    const incline::Family f = incline::make_family(o);
    write_report_if_requested(s->report, [&] { return incline_families_report(o, f); });
    io::AtomicFile file(s->out);
    const bool phi = o.vary == incline::FamilyParameter::phi;
    const std::string column = phi ? "phi_deg" : s->vary;
    file.stream() << column << ",t,x,y,vx,vy,ax,ay\n";
    json members = json::array();
    for (const auto& m : f.members) {
      const double shown = phi ? incline::rad_to_deg(m.value) : m.value;
      for (const auto& st : m.trajectory) {
        file.stream() << io::format_number(shown) << ',';
        write_state(file.stream(), st);
      }
      const auto& pr = m.prediction;
      json e;
      e[column] = shown;
      e["k"] = finite_or_null(pr.k);
      e["regime"] = incline::to_string(pr.regime);
      e["t_stop"] = opt(pr.t_stop);
      e["x_stop"] = opt(pr.x_stop);
      e["y_stop"] = opt(pr.y_stop);
      e["x_limit"] = opt(pr.x_limit);
      e["t_end"] = m.t_end;
      const double v0 = m.parameters.v0;
      const bool stops = pr.t_stop && v0 > 0;
      e["t_stop_over_v0"] = stops ? json(*pr.t_stop / v0) : json(nullptr);
      e["x_stop_over_v0_sq"] = stops ? json(*pr.x_stop / (v0 * v0)) : json(nullptr);
      e["y_stop_over_v0_sq"] = stops ? json(*pr.y_stop / (v0 * v0)) : json(nullptr);
      e["y_stop_over_x_stop"] = stops && *pr.x_stop > 0 ? json(*pr.y_stop / *pr.x_stop) : json(nullptr);
      members.push_back(e);
    }
    file.commit();
    json j;
    j["vary"] = s->vary;
    j["t_end"] = f.t_end;
    j["rows"] = f.members.size() * f.members.front().trajectory.size();
    j["members"] = members;
    j["warnings"] = f.warnings;
    j["out"] = s->out;
    print_result(j, s->json);
  });
}

}  // namespace

void register_incline(CLI::App& root) {
  auto* area = root.add_subcommand("incline", "Disc launched across a rough incline (seed 000)");
  area->require_subcommand(1);
  add_predict(area);
  add_simulate(area);
  add_mu_from_stop(area);
  add_families(area);
  add_incline_analysis_commands(area);
}

}  // namespace tribolab::cli
