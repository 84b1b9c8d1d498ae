#include "app/common/study_citation.hpp"
#include "app/bounce/report_bounce_series.hpp"

#include "analysis/series_plausibility.hpp"

#include "app/bounce/report_bounce.hpp"
#include "app/bounce/report_bounce_analysis.hpp"
#include "app/common/series_files.hpp"
#include "app/incline/report_incline_series.hpp"
#include "app/common/report_util.hpp"

#include "report/format.hpp"
#include "report/html.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace tribolab::app {
namespace {

using analysis::BounceSeriesPoint;
using analysis::BounceSeriesSummary;
using report::Figure;
using report::format_uncertain;
using report::format_value;
using report::Series;
using report::Table;


Figure series_figure(std::string title, std::string x, std::string y, int height = 420) {
  return make_figure(std::move(title), std::move(x), std::move(y), height);
}

std::string mean_cell(const analysis::WeightedMean& m) {
  if (m.n == 0) return "—";
  return format_uncertain(m.mean, m.sigma_scaled);
}

std::string consistency(const analysis::WeightedMean& m) {
  if (m.dof <= 0) return "one run: no test";
  return "χ² = " + format_value(m.chi2) + " on " + std::to_string(m.dof) + " dof, p = " + format_value(m.p_value);
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

int add_bounce_series(report::Report& rep, const std::string& prefix, const std::vector<BounceSeriesRun>& runs,
                      const std::vector<BounceSeriesPoint>& points, const BounceSeriesSummary& s,
                      const analysis::BounceSeriesOptions& o, const std::vector<std::string>& links) {
  // Point j belongs to the j-th analysed run.
  std::vector<std::size_t> run_of_point;
  std::vector<std::string> point_files;
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (runs[i].analysis) {
      run_of_point.push_back(i);
      point_files.push_back(file_name(runs[i].source));
    }
  const std::size_t n_failed = runs.size() - run_of_point.size();
  int figures = 0;

  auto& sum = rep.add_section(prefix + "Series summary");
  sum.add_paragraph(std::to_string(runs.size()) + " files, " + std::to_string(run_of_point.size()) + " analysed" +
                    (n_failed ? ", " + std::to_string(n_failed) + " failed (their errors are in the table of runs)" : "") +
                    ". Each run is the rugby-ball study's experiment 1 on one tracked bounce; together they are its experiment 2 "
                    "(figure 32) and the comparisons of its discussion (figures 49, 50, 52).");
  {
    Table t;
    t.caption = "The series at a glance (weighted means ± their standard error, inflated by sqrt(χ²/dof) when "
                "the runs scatter more than their errors)";
    t.header = {"quantity", "value", "note"};
    // Runs that are not one quantity (e at different collision angles) get no mean: the
    // headline is the relation with the angle (figure "e against collision angle" below).
    if (analysis::is_one_value(s.e_velocity))
      t.rows.push_back({"e from velocities, weighted mean", mean_cell(s.e_velocity), consistency(s.e_velocity)});
    else
      t.rows.push_back({"e from velocities", analysis::e_velocity_headline(s), consistency(s.e_velocity)});
    if (analysis::is_one_value(s.e_height))
      t.rows.push_back({"e from apex heights, weighted mean", mean_cell(s.e_height), consistency(s.e_height)});
    else
      t.rows.push_back({"e from apex heights", "not one value across the runs: no mean is shown", consistency(s.e_height)});
    auto above = [&](const analysis::AboveOne& a) {
      return std::to_string(a.above) + " of " + std::to_string(a.n) + " (" + std::to_string(a.significant) +
             " significantly)";
    };
    const std::string z_note = "significantly: (e − 1)/σ_e > " + format_value(o.z_above_one) + " (one-sided 95 %)";
    t.rows.push_back({"runs with e_v > 1", above(s.above_one_velocity), z_note});
    t.rows.push_back({"runs with e_h > 1", above(s.above_one_height), z_note});
    t.rows.push_back({"kinetic energy after / before, mean", format_value(s.energy_ratio_mean),
                      std::to_string(s.n_energy_gain) + " run(s) gained energy"});
    if (s.n_force > 0) {
      t.rows.push_back({"mean normal force, mean ± sd (N)", format_uncertain(s.force_mean, s.force_sd),
                        std::to_string(s.n_force) + " run(s) with a contact duration"});
      t.rows.push_back({"correlation of the mean force with e_v", format_value(s.force_e_correlation),
                        "Pearson r (the study: a higher mean force gives a higher rebound)"});
    }
    if (!points.empty()) {
      const auto& f = points[s.fastest_contact_run];
      const auto& w = points[s.slowest_contact_run];
      t.rows.push_back({"fastest contact point (m/s)", format_value(f.contact_point_speed),
                        point_files[s.fastest_contact_run] + " at " + format_value(f.collision_angle_deg) + " deg"});
      t.rows.push_back({"slowest contact point (m/s)", format_value(w.contact_point_speed),
                        point_files[s.slowest_contact_run] + " at " + format_value(w.collision_angle_deg) + " deg"});
    }
    sum.add_table(std::move(t));
  }
  if (s.outliers.empty()) {
    sum.add_paragraph("Outliers: none (a run is named when its e_v lies more than " + format_value(o.outlier_z) +
                      " robust deviations from the median of its angle bin, in bins of at least " +
                      std::to_string(o.outlier_min_bin) + " runs).");
  } else {
    std::vector<std::string> items;
    for (const auto& out : s.outliers) items.push_back(point_files[out.run] + ": " + out.reason);
    sum.add_paragraph("Outliers (modified z-score of Iglewicz & Hoaglin > " + format_value(o.outlier_z) +
                      " within the run's angle bin). e also depends on the spin and speed of the throw, so such a run "
                      "may be a different kind of throw rather than a bad measurement: look at its own report.");
    sum.add_list(std::move(items));
  }

  auto& e = rep.add_section(prefix + "Restitution against the collision angle (rugby-ball study, figure 32)");
  {
    Figure f = series_figure("e against the collision angle", "collision angle θ (deg)", "restitution e");
    Series ev = named("e from velocities (± 1 s.e.)"), eh = named("e from apex heights (± 1 s.e.)");
    for (const auto& p : points) {
      ev.x.push_back(p.collision_angle_deg);
      ev.x_error.push_back(p.sigma_collision_angle_deg);
      ev.y.push_back(p.e_velocity);
      ev.y_error.push_back(p.sigma_e_velocity);
      if (std::isfinite(p.e_height)) {
        eh.x.push_back(p.collision_angle_deg);
        eh.y.push_back(p.e_height);
        eh.y_error.push_back(p.sigma_e_height);
      }
    }
    // Angle error bars only when every run has one (none with a bracketed floor).
    if (!std::all_of(ev.x_error.begin(), ev.x_error.end(), [](double v) { return std::isfinite(v); })) ev.x_error.clear();
    f.series.push_back(std::move(ev));
    if (!eh.x.empty()) f.series.push_back(std::move(eh));
    Series bins = named("weighted mean of e_v per " + format_value(o.bin_width_deg) + "° bin", report::Mode::LinesMarkers);
    for (const auto& b : s.bins) {
      bins.x.push_back(b.centre_deg);
      bins.y.push_back(b.e_velocity.mean);
      bins.y_error.push_back(b.e_velocity.sigma_scaled);
    }
    f.series.push_back(std::move(bins));
    Series one = named("e = 1 (rebound to the drop height)", report::Mode::Lines);
    one.dash = report::Dash::Dash;
    one.color = "black";
    one.x = {0, 180};
    one.y = {1, 1};
    f.series.push_back(std::move(one));
    f.caption = "The rugby-ball study's figure 32 redrawn: each run at its collision angle at first touch (the angle at "
                "the centre between the contact point and the rear tip, as the study's figure 30 defines it). Above the "
                "dashed line the ball rose higher than it fell.";
    e.add_figure(std::move(f));
    ++figures;
  }
  {
    Table t;
    t.caption = "Restitution per " + format_value(o.bin_width_deg) + "° bin of collision angle";
    t.header = {"angle (deg)", "runs", "e_v weighted mean", "consistency", "e_v range", "e_v > 1"};
    for (const auto& b : s.bins) {
      t.rows.push_back({format_value(b.low_deg) + "–" + format_value(b.high_deg), std::to_string(b.n), mean_cell(b.e_velocity),
                        consistency(b.e_velocity), format_value(b.e_min) + " – " + format_value(b.e_max), std::to_string(b.n_above_one)});
    }
    e.add_table(std::move(t));
  }

  auto& en = rep.add_section(prefix + "Energies and mean normal force per run (rugby-ball study, figures 49, 50)");
  {
    Figure f = series_figure("kinetic energy before and after each bounce", "run", "kinetic energy (J)");
    struct Kind {
      const char* name;
      double (*value)(const bounce::KineticEnergy&);
    };
    const Kind kinds[] = {{"total", [](const bounce::KineticEnergy& k) { return k.total(); }},
                          {"translational", [](const bounce::KineticEnergy& k) { return k.translational_x + k.translational_y; }},
                          {"rotational", [](const bounce::KineticEnergy& k) { return k.rotational; }}};
    for (const Kind& k : kinds)
      for (bool after : {false, true}) {
        Series sr = named(std::string(k.name) + (after ? " after" : " before"));
        for (std::size_t j = 0; j < points.size(); ++j) {
          sr.x.push_back(static_cast<double>(run_of_point[j] + 1));
          sr.y.push_back(k.value(after ? points[j].energy_post : points[j].energy_pre));
        }
        f.series.push_back(std::move(sr));
      }
    f.caption = "E = m v_x²/2 + m v_y²/2 + I ω²/2 before at first touch, after at separation (rugby-ball study, discussion 1 (討論 (一))); runs numbered as in the table "
                "of runs.";
    en.add_figure(std::move(f));
    ++figures;
  }
  if (s.n_force > 0) {
    Figure f = series_figure("mean normal force per run", "run", "mean normal force (N)");
    Series sr = named("N_mean = normal impulse / T (± 1 s.e.)");
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (!std::isfinite(points[j].mean_normal_force)) continue;
      sr.x.push_back(static_cast<double>(run_of_point[j] + 1));
      sr.y.push_back(points[j].mean_normal_force);
      sr.y_error.push_back(points[j].sigma_mean_normal_force);
    }
    f.series.push_back(std::move(sr));
    f.caption = "The rugby-ball study, discussion 2 (討論 (二)): at equal contact durations a higher mean force should give a higher rebound.";
    en.add_figure(std::move(f));
    ++figures;
  } else {
    en.add_paragraph("No mean normal force: give --contact-duration to compute it (rugby-ball study, discussion 2 (討論 (二))).");
  }

  auto& cp = rep.add_section(prefix + "Contact-point speed against the collision angle (rugby-ball study, figure 52)");
  {
    Figure f = series_figure("speed of the contact point at first touch", "collision angle θ (deg)", "velocity (m/s)");
    Series sp = named("|v_p| (± 1 s.e.)"), vx = named("v_p,x (slip)"), vy = named("v_p,y");
    for (const auto& p : points) {
      sp.x.push_back(p.collision_angle_deg);
      sp.y.push_back(p.contact_point_speed);
      sp.y_error.push_back(p.sigma_contact_point_speed);
      vx.x.push_back(p.collision_angle_deg);
      vx.y.push_back(p.contact_point_vx);
      vy.x.push_back(p.collision_angle_deg);
      vy.y.push_back(p.contact_point_vy);
    }
    f.series.push_back(std::move(sp));
    f.series.push_back(std::move(vx));
    f.series.push_back(std::move(vy));
    f.caption = "Velocity of the material point at the support point, v_p = v + ω × r (rugby-ball study, figure 51-c), "
                "at first touch, from the pre-impact flight. The study finds it largest at 50–70° and small at "
                "120–125°, where the ball tends to roll.";
    cp.add_figure(std::move(f));
    ++figures;
  }

  auto& rs = rep.add_section(prefix + "Runs");
  {
    Table t;
    t.caption = "Every run (the file links to its own report when one was written)";
    t.header = {"file", "run", "collision angle (deg)", "e_v", "e_h", "E before (J)", "E after (J)",
                "mean force (N)", "|v_p| (m/s)", "note"};
    std::size_t j = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const std::string run = std::to_string(i + 1);
      if (!runs[i].analysis) {
        t.rows.push_back({file_name(runs[i].source), run, "—", "—", "—", "—", "—", "—", "—", "failed: " + runs[i].error});
        continue;
      }
      const auto& p = points[j];
      std::string note;
      for (const auto& out : s.outliers)
        if (out.run == j) note = "outlier";
      if (p.e_velocity > 1) note += std::string(note.empty() ? "" : ", ") + "e_v > 1";
      t.rows.push_back({file_name(runs[i].source), run, format_value(p.collision_angle_deg),
                        format_uncertain(p.e_velocity, p.sigma_e_velocity), format_uncertain(p.e_height, p.sigma_e_height),
                        format_value(p.energy_pre.total()), format_value(p.energy_post.total()),
                        format_uncertain(p.mean_normal_force, p.sigma_mean_normal_force),
                        format_uncertain(p.contact_point_speed, p.sigma_contact_point_speed), note});
      ++j;
    }
    t.links = links;
    rs.add_table(std::move(t));
  }
  return figures;
}

report::Report bounce_analyze_series_report(const std::string& command, const bounce::Ball& ball,
                                            const std::vector<BounceSeriesRun>& runs,
                                            const std::vector<BounceSeriesPoint>& points,
                                            const BounceSeriesSummary& summary,
                                            const analysis::BounceSeriesOptions& options,
                                            const std::string& report_path,
                                            const std::function<std::string(std::size_t)>& run_command,
                                            report::PlotlyMode plotly) {
  std::vector<std::string> sources;
  for (const auto& run : runs) sources.push_back(run.source);
  const std::vector<std::string> links =
      write_run_reports(sources, report_path, plotly, [&](std::size_t i) -> std::optional<report::Report> {
        if (!runs[i].analysis) return std::nullopt;
        return with_study_source(bounce_analyze_report(run_command(i), ball, *runs[i].analysis), Study::rugby_ball);
      });
  report::Report rep;
  rep.title = "tribolab bounce analyze: a series of " + std::to_string(runs.size()) + " bounces";
  rep.subtitle = command;
  add_bounce_series(rep, "", runs, points, summary, options, links);
  std::vector<const analysis::BounceAnalysis*> analyses;
  for (const auto& run : runs) analyses.push_back(run.analysis);
  if (const auto w = analysis::bounce_series_warnings(analyses, sources); !w.empty()) {
    auto& ws = rep.add_section("Warnings");  // docs/theory.md#plausibility-checks
    ws.add_list(w);
  }
  auto& b = rep.add_section("Ball");
  b.add_table(ball_table(ball));
  return rep;
}

}  // namespace tribolab::app
