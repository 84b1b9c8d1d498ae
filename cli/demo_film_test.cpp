// The demo's film case study (src/app/demo/demo_film.cpp) holds the truth: the rendered throw, tracked
// back with the ellipse tracker and analysed as `bounce analyze` does, gives the simulation's
// numbers within their uncertainties or a fraction of a percent (stated below), and the files
// the report links are written.
#include "cli_test_util.hpp"
#include "app/demo/demo.hpp"
#include "app/demo/demo_bounce_truth.hpp"
#include "app/demo/demo_film.hpp"

#include "report/format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using namespace tribolab::app;  // the demo lives in the application layer

namespace fs = std::filesystem;

/// The checks of `c` as text, for failure messages.
std::string describe(const FilmCase& c) {
  std::ostringstream why;
  const auto& e = c.error;
  why << "tracking: centre " << e.median_centre_px << " px (largest " << e.max_centre_px << "), tips "
      << e.median_tip_px << " px (largest " << e.max_tip_px << "), axis " << e.median_axis_deg
      << " deg; frames " << c.film.frames << "\n";
  for (const auto& k : bounce_truth_checks(c.analysis, c.truth, c.options.motion.ball))
    why << k.quantity << ": " << report::format_uncertain(k.value, k.sigma) << " truth " << k.truth
        << (k.covered() ? "" : "  <- outside the 95% interval") << "\n";
  return why.str();
}

/// The case study run once for all tests (rendering and tracking take a few seconds).
const FilmCase& film_case() {
  static const FilmCase c = run_film_case(testing::temp_dir("demo_film"));
  return c;
}

TEST(DemoFilm, TrackedThrowHoldsTheTruth) {
  const FilmCase& c = film_case();
  const std::string why = describe(c);
  for (const auto& f : {c.video, c.csv, c.tracking_report}) EXPECT_TRUE(fs::exists(f)) << f;
  // A short film keeps the demo fast: 240 fps, about half a second.
  EXPECT_GE(c.film.frames, 100);
  EXPECT_LE(c.film.frames, 140);
  // Nothing lost, and the tracks lie on the truth. The issue asks for a centre within 0.5 px
  // and an orientation within 0.5 deg (median) on a spinning, blurred, noisy ellipse; the
  // report's text says "a few hundredths of a pixel", held here as a median below 0.05 px.
  const auto& e = c.error;
  EXPECT_EQ(e.frames, c.film.frames) << why;
  EXPECT_LT(e.median_centre_px, 0.05) << why;
  EXPECT_LT(e.median_tip_px, 0.5) << why;
  EXPECT_LT(e.median_axis_deg, 0.5) << why;
  for (const auto& s : c.tracked.series) EXPECT_TRUE(s.lost_ranges.empty()) << s.name;
  // Every quantity holds its truth: inside its 95 % interval, or within 0.5 % of the truth (half
  // of the 1 % to which the seed reads e and the spins). The second clause is needed: the
  // intervals count only the scatter about the fits, while the tracker's errors of a few
  // hundredths of a pixel and degree change slowly along the path; here the spin after the
  // bounce is -9.5056 +- 0.0038 against -9.5198 rad/s (3.7 sigma, 0.15 %). Filmed without blur
  // (exposure 0) it is -9.5348 +- 0.0056 (2.7 sigma, 0.16 %): not blur alone.
  int covered = 0;
  const auto checks = bounce_truth_checks(c.analysis, c.truth, c.options.motion.ball);
  for (const auto& k : checks) {
    covered += k.covered() ? 1 : 0;
    EXPECT_TRUE(k.covered() || std::abs(k.value - k.truth) <= 5e-3 * std::abs(k.truth)) << k.quantity << "\n" << why;
  }
  // Honest 95 % intervals leave 0.7 of 14 truths outside on average: at least 12 must be inside.
  EXPECT_GE(covered, 12) << why;
}

TEST(DemoFilm, CaseStudyLinksTheTrackingReport) {
  const FilmCase& c = film_case();
  report::Report r;
  std::ostringstream log;
  add_film_sections(r, c, log);
  ASSERT_EQ(r.sections.size(), 1u);
  EXPECT_EQ(r.validate(), "");
  EXPECT_EQ(r.figure_count(), 6);  // the six figures of `bounce analyze --report`
  bool linked = false, gallery = false;
  std::string text;
  for (const auto& b : r.sections.front().blocks) {
    if (const auto* t = std::get_if<report::Table>(&b))
      linked = linked || (!t->links.empty() && t->links.front() == "film_tracking.html");
    if (const auto* g = std::get_if<report::Gallery>(&b)) gallery = g->images.size() == 6;
    if (const auto* p = std::get_if<report::Paragraph>(&b)) text += p->text + "\n";
  }
  EXPECT_TRUE(linked);
  EXPECT_TRUE(gallery);
  // The text names every quantity whose truth is outside its interval, or says there is none.
  int outside = 0;
  for (const auto& k : bounce_truth_checks(c.analysis, c.truth, c.options.motion.ball)) {
    if (k.covered()) continue;
    ++outside;
    EXPECT_NE(text.find(k.quantity + " " + report::format_uncertain(k.value, k.sigma) + " against"), std::string::npos)
        << k.quantity << "\n" << text;
  }
  if (outside == 0) {
    EXPECT_NE(text.find("Every truth lies inside its 95 % interval."), std::string::npos) << text;
  }
  EXPECT_EQ(testing::count_lines(log.str()), 1) << log.str();
  const std::string html = testing::slurp(c.tracking_report);
  std::size_t plots = 0;
  for (auto p = html.find("class=\"tribolab-plot\""); p != std::string::npos; p = html.find("class=\"tribolab-plot\"", p + 1))
    ++plots;
  EXPECT_EQ(plots, 4u);  // x, y, orientation, score
}

/// A command the report shows, run from the demo folder `dir`: its relative paths made absolute.
std::string from_folder(std::string command, const std::string& dir) {
  command = command.substr(std::string("tribolab ").size());
  for (const std::string rel : {"data/film/", "film_tracking.html", "film_bounce.html"}) {
    for (auto p = command.find(" " + rel); p != std::string::npos; p = command.find(" " + rel, p + dir.size() + 2))
      command.insert(p + 1, dir + "/");
  }
  return command;
}

TEST(DemoFilm, TrackVideoCommandShownWritesTheSameTracks) {
  const FilmCase& c = film_case();
  const std::string dir = fs::path(c.tracking_report).parent_path().string();
  const std::string before = testing::slurp(c.csv);
  ASSERT_FALSE(before.empty());
  fs::remove(c.tracking_report);
  const auto j = testing::run_json(from_folder(film_commands(c)[0], dir));
  // The command is the workflow the case study called: the same tracks. Its world positions
  // agree to 1e-9 m (measured: 1e-12 m, the calibration rebuilt from the printed --scale and
  // --origin rounds differently in the last bits), a millionth of a pixel.
  const auto rows = [](const std::string& text) {
    std::vector<std::vector<std::string>> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> cells;
      std::istringstream ls(line);
      for (std::string cell; std::getline(ls, cell, ',');) cells.push_back(cell);
      out.push_back(cells);
    }
    return out;
  };
  const auto a = rows(before), b = rows(testing::slurp(c.csv));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 1; i < a.size(); ++i) {
    ASSERT_EQ(a[i].size(), b[i].size()) << i;
    EXPECT_EQ(a[i][0] + a[i][1], b[i][0] + b[i][1]) << i;  // track and frame
    for (std::size_t k = 2; k < a[i].size(); ++k) {
      if (a[i][k].empty()) continue;  // a lost row: no position
      EXPECT_NEAR(std::stod(a[i][k]), std::stod(b[i][k]), 1e-9) << i << " " << k;
    }
  }
  EXPECT_TRUE(fs::exists(c.tracking_report));
  EXPECT_EQ(j["frames"].get<int>(), c.tracked.frames) << j;
}

TEST(DemoFilm, BounceAnalyzeCommandShownGivesTheSameNumbers) {
  const FilmCase& c = film_case();
  const std::string dir = fs::path(c.tracking_report).parent_path().string();
  const auto commands = film_commands(c);
  ASSERT_EQ(commands.size(), 2u);
  const auto j = testing::run_json(from_folder(commands[1], dir));
  // The command reads the tracks the shown `track video` command wrote (above: the same to
  // 1e-9 m), so its numbers agree far inside their uncertainties (to 1e-6 relative).
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::abs(b); };
  EXPECT_TRUE(near(j["e_velocity"].get<double>(), c.analysis.e_velocity)) << j["e_velocity"];
  EXPECT_TRUE(near(j["sigma_e_velocity"].get<double>(), c.analysis.sigma_e_velocity)) << j["sigma_e_velocity"];
  EXPECT_TRUE(near(j["collision_angle_deg"].get<double>(), c.analysis.collision_angle_deg));
  EXPECT_TRUE(near(j["t_touch"].get<double>(), c.analysis.t_touch));
  EXPECT_TRUE(fs::exists(dir + "/film_bounce.html"));
}

}  // namespace
}  // namespace tribolab::cli
