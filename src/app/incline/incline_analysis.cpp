#include "app/incline/incline_analysis.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"
#include "app/common/series_json.hpp"

#include "app/incline/incline_launch.hpp"
#include "app/incline/report_incline_analysis.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "io/theta_c_table.hpp"
#include "io/track_csv.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <cmath>

namespace tribolab::app {

using nlohmann::json;

const Fields<InclineTrackInput>& incline_track_input_fields() {
  using O = InclineTrackInput;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("track", &O::track, "", "track to analyse (required when the file holds several)");
    d.add("time_scale", &O::time_scale, "", "real seconds per file second (slow motion 240 fps shown at 30 fps: 0.125)")
        .in(ranges::time_scale);
    d.add("length_unit", &O::length_unit, "",
          "unit of the file's lengths, overriding what the file says: m, cm, mm, km, um, in, ft (when not given: the "
          "file's unit, else m)");
    return d;
  }();
  return f;
}

const Fields<InclineNormalFrictionTestOptions>& incline_normal_friction_test_fields() {
  using O = InclineNormalFrictionTestOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("files", &O::files, "", "tracked runs, one per angle (with phi_deg)").as(FieldRole::input_files);
    d.add("phi_deg", &O::phi_deg, "deg", "comma-separated incline angles, in (0, 90), one per file");
    d.add("table", &O::table, "", "CSV with columns phi_deg,cos_theta_c[,sigma_cos_theta_c] instead of files");
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.group(&O::input, incline_track_input_fields());
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

track::Track read_incline_track(const std::string& file, const InclineTrackInput& in) {
  io::ImportOptions o;
  o.time_scale = check_range(in.time_scale, ranges::time_scale, field("time_scale"));
  o.length_unit = in.length_unit;
  if (!in.track.empty()) o.tracks = {in.track};
  const track::TrackSet set = io::read_tracks(file, o);
  if (!in.track.empty()) return set.find(in.track);
  std::vector<const track::Track*> with_points;
  for (const auto& t : set.tracks)
    if (!t.points.empty()) with_points.push_back(&t);
  if (with_points.size() == 1) return *with_points.front();
  std::string names;
  for (const auto* t : with_points) names += (names.empty() ? "'" : ", '") + t->name + "'";
  throw InputError(set.source, "the file holds " + std::to_string(with_points.size()) + " tracks (" +
                                   names + "); choose one with " + field("track"));
}

// ---- synth ----------------------------------------------------------------------------

InclineSynthResult incline_synth(const InclineSynthOptions& s) {
  check_output_paths({}, {{"out", s.out}});  // before any work (app/common/output_paths.hpp)
  auto need = [](const std::optional<double>& v, const std::string& option) {
    if (!v) throw MissingOptionError(option, "is required");
    return *v;
  };
  analysis::InclineSynthOptions o;
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  o.params.mu = check_range(need(s.mu, field("mu")), ranges::friction, field("mu"));
  if (!(o.params.mu > 0)) throw InputError(field("mu"), "must be > 0, got " + io::format_number(o.params.mu));
  o.params.phi = to_rad(check_incline_angle_deg(need(s.phi_deg, field("phi_deg")), field("phi_deg"), true));
  o.params.v0 = check_range(need(s.v0, field("v0")), ranges::speed, field("v0"));
  o.params.g = check_range(s.g, ranges::gravity, field("g"));
  o.params.normal_accel = check_range(s.normal_accel, ranges::accel, field("normal_accel"));
  o.fps = check_range(s.fps, ranges::frame_rate, field("fps"));
  o.noise = check_range(s.noise, ranges::noise, field("noise"));
  if (!(std::abs(s.frame_rotation_deg) <= 20))
    throw InputError(field("frame_rotation_deg"),
                     "must be within [-20, 20] deg, got " + io::format_number(s.frame_rotation_deg));
  o.frame_rotation = to_rad(s.frame_rotation_deg);
  if (s.seed > 9007199254740992ULL) throw InputError(field("seed"), "must be an integer >= 0, got " + std::to_string(s.seed));
  o.seed = s.seed;
  o.t_launch = check_range(s.t_offset, ranges::duration, field("t_offset"));
  o.x0 = check_range(s.x0, ranges::position, field("x0"));
  o.y0 = check_range(s.y0, ranges::position, field("y0"));
  o.duration = s.duration ? check_range(*s.duration, ranges::duration, field("duration")) : 0.0;
  if (s.format != "export" && s.format != "csv")
    throw InputError(field("format"), "must be export or csv, got '" + s.format + "'");
  if (s.track_name.empty() || s.track_name.find_first_of(",\t;\n\"") != std::string::npos)
    throw InputError(field("track_name"), "must be a non-empty name without , ; tab or quotes");
  o.track_name = s.track_name;
  if (const std::string e = o.validate(); !e.empty()) throw InputError("incline synth", e);
  InclineSynthResult res;
  const analysis::InclineSynthRun& run = res.run = analysis::synthesize_incline_run(o);

  if (!s.out.empty()) {
    io::AtomicFile file(s.out);
    if (s.format == "csv") {
      track::TrackSet set;
      set.tracks.push_back(run.track);
      io::write_tidy_csv(file.stream(), set);
    } else {
      file.stream() << io::write_export_text({run.track});
    }
    file.commit();
  }
  json& j = res.json;
  j["points"] = run.track.points.size();
  j["t_launch"] = o.t_launch;
  j["t_stop"] = json_number(run.t_stop);
  j["x_stop"] = run.t_stop ? json(run.truth.back().x) : json(nullptr);
  j["y_stop"] = run.t_stop ? json(run.truth.back().y) : json(nullptr);
  j["model"] = o.params.normal_accel != 0 ? "A" : "B";
  j["format"] = s.format;
  j["track"] = o.track_name;
  j["out"] = s.out.empty() ? json(nullptr) : json(s.out);
  return res;
}

const ResultKeys& incline_synth_result_keys() {
  static const ResultKeys k = {
      {"points", "", "marked points written"}, {"t_launch", "s", "launch instant in the file's time"},
      {"t_stop", "s", "stop instant in the file's time"}, {"x_stop", "m", ""}, {"y_stop", "m", ""},
      {"model", "", "A or B"}, {"format", "", ""}, {"track", "", ""}, {"out", "", ""},
  };
  return k;
}

// ---- normal-friction-test -------------------------------------------------------------

InclineNormalFrictionTestResult incline_normal_friction_test(const InclineNormalFrictionTestOptions& s) {
  std::vector<std::string> inputs = s.files;
  if (!s.table.empty()) inputs.push_back(s.table);
  check_output_paths(inputs, {{"report", s.report}});  // before any work (app/common/output_paths.hpp)
  std::vector<analysis::ThetaCPoint> pts;
  std::vector<std::string> warnings;  // each run's, with its file (as `incline series` prints them)
  InclineNormalFrictionTestResult res;
  json failed_rows = json::array();  // {"source", "phi_deg", "error"} of the runs that failed
  if (!s.table.empty()) {
    if (!s.files.empty() || !s.phi_deg.empty())
      throw InputError(field("table"), "give either " + field("table") + " or tracked files with " + field("phi_deg") + ", not both");
    pts = io::read_theta_c_table(s.table);
  } else {
    if (s.files.empty()) throw InputError("normal-friction-test", "give tracked files with " + field("phi_deg") + ", or " + field("table"));
    if (s.phi_deg.empty()) throw MissingOptionError(field("phi_deg"), "is required with tracked files (one angle per file)");
    if (s.phi_deg.size() != s.files.size())
      throw InputError(field("phi_deg"), "gives " + std::to_string(s.phi_deg.size()) + " angles for " +
                                        std::to_string(s.files.size()) + " files");
    const double g = check_range(s.g, ranges::gravity, field("g"));
    std::vector<double> phi(s.files.size());
    for (std::size_t i = 0; i < s.files.size(); ++i)
      phi[i] = to_rad(check_incline_angle_deg(s.phi_deg[i], field("phi_deg"), false));
    // A series (docs/cli.md#several-runs): a bad file becomes its row's error, the fit uses
    // the others.
    struct Run {
      analysis::ThetaCPoint point;
      std::vector<std::string> warnings;
    };
    const auto runs = analysis::run_series<Run>(s.files, [&](std::size_t i, const std::string& file) {
      // Model B only: theta_c of each run, at its v_y extremum (seed 000, 圖三-2).
      analysis::InclineFitOptions o;
      o.phi = phi[i];
      o.g = g;
      o.fit_model_a = false;
      const track::Track t = read_incline_track(file, s.input);
      const analysis::InclineAnalysis a = analysis::analyze_incline_run(t, o);
      if (!a.theta_c) {
        // Times wrong by a factor stretch the run past its extremum's window: the cause to name
        // is the factor (issue 27: times 8x and 16x too long said only "no v_y extremum").
        if (a.gravity && a.gravity->implausible)
          throw InputError(file, analysis::gravity_warning(*a.gravity, o) + " (no v_y extremum found)");
        throw InputError(file, "no v_y extremum found (" +
                                   (a.notes.empty() ? std::string("the disc does not stop") : a.notes.back()) + ")");
      }
      return Run{{o.phi, a.theta_c->cos_theta_c, a.theta_c->sigma_cos_theta_c, file}, a.warnings};
    });
    for (const auto& r : runs) {
      if (!r.ok()) {
        failed_rows.push_back({{"source", r.source}, {"phi_deg", to_deg(phi[&r - runs.data()])}, {"error", r.located_error()}});
        continue;
      }
      pts.push_back(r.result->point);
      for (const auto& w : r.result->warnings) warnings.push_back(r.source + ": " + w);
    }
    res.errors = series_errors(runs);
    if (pts.empty()) throw InputError(res.errors.front() + (runs.size() > 1 ? " (and every other run failed)" : ""));
    // Too few runs left for the line: say why the others failed, not only how many are left.
    if (pts.size() < 3 && !res.errors.empty())
      throw InputError("normal-friction-test", "needs at least 3 runs with theta_c, got " + std::to_string(pts.size()) +
                                                   ": " + res.errors.front() +
                                                   (res.errors.size() > 1 ? " (and " + std::to_string(res.errors.size() - 1) + " more)" : ""));
  }
  const analysis::NormalFrictionTest& r = res.test = analysis::normal_friction_test(pts);
  json runs = json::array();
  for (const auto& p : r.points) {
    res.tan_phi.push_back(std::tan(p.phi));
    res.cos_theta_c.push_back(p.cos_theta_c);
    runs.push_back({{"source", p.source},
                    {"phi_deg", to_deg(p.phi)},
                    {"tan_phi", std::tan(p.phi)},
                    {"cos_theta_c", p.cos_theta_c},
                    {"sigma_cos_theta_c", p.sigma_cos_theta_c > 0 ? json(p.sigma_cos_theta_c) : json(nullptr)}});
  }
  json& j = res.json;
  j["mu"] = r.mu;
  j["sigma_mu"] = r.sigma_mu;
  j["slope"] = r.slope;
  j["sigma_slope"] = r.sigma_slope;
  j["intercept"] = r.intercept;
  j["sigma_intercept"] = r.sigma_intercept;
  j["intercept_ci95"] = json::array({r.intercept_ci_low, r.intercept_ci_high});
  j["r_squared"] = r.line.r_squared;
  j["verdict"] = to_string(r.verdict);
  j["test_size"] = 0.05;
  j["meaning"] = "present when the 95 % interval of the intercept of cos(theta_c) against tan(phi) excludes 0 "
                 "(eq c): about one series in twenty without normal friction is called present";
  j["n_runs"] = r.points.size();
  for (auto& row : failed_rows) runs.push_back(std::move(row));
  j["runs"] = runs;
  j["n_failed"] = res.errors.size();
  j["warnings"] = warnings;
  if (!s.report.empty()) report::write_html(incline_normal_test_report(r), s.report, s.plotly);
  return res;
}


const ResultKeys& incline_normal_friction_test_result_keys() {
  static const ResultKeys k = {
      {"mu", "", "1/slope"}, {"slope", "", "of cos(theta_c) against tan(phi)"}, {"intercept", "", ""},
      {"r_squared", "", ""}, {"verdict", "", ""}, {"test_size", "", ""}, {"meaning", "", ""}, {"n_runs", "", ""},
      {"runs.source", "", ""}, {"runs.phi_deg", "deg", ""}, {"runs.tan_phi", "", ""}, {"runs.cos_theta_c", "", ""},
      {"runs.error", "", ""}, {"n_failed", "", ""}, {"warnings", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
