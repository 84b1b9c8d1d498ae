// The first section of the demo report: what tribolab is, where the two studies come from,
// and the conventions every later section uses (docs/theory.md).
#include "app/demo/demo.hpp"
#include "report/plotly_script.hpp"
#include "app/common/study_citation.hpp"

namespace tribolab::app {

void add_about_section(report::Report& r, std::ostream& log) {
  auto& s = r.add_section("About this report");
  s.add_paragraph(
      "tribolab is a C++ toolkit and command-line program for the mechanics of friction and "
      "impact experiments. It reads motion tracked in video with Tracker, does the analyses of "
      "two student research projects automatically and with stated uncertainties, simulates "
      "and predicts with verified models, fits model parameters to data and sweeps parameter "
      "spaces. This report was written by the command “tribolab demo”: every result in it is computed by "
      "tribolab when the report is written, from data files that ship with the project.");

  s.add_subheading("The two studies");
  s.add_paragraph(
      "tribolab was built from two Taiwanese high-school research projects, both shown at the "
      "Taiwan National Primary and High School Science Fair (中華民國中小學科學展覽會), senior high "
      "school division, physics and astronomy, and both awarded third place. This report calls "
      "them the incline study and the rugby-ball study; figure, table and equation numbers in "
      "it are the studies' own, the Chinese numerals of the papers given beside their reading, "
      "e.g. equation 10A (十A).");
  s.add_list({
      study_citation(Study::incline) +
          " A disc launched horizontally across a rough incline: closed-form motion (its "
          "equations 1–10A (一–十A)), stopping time and position, a test for a friction component "
          "normal to the path, and the friction coefficient measured from the stopping point alone.",
      study_citation(Study::rugby_ball) +
          " A spinning rugby ball (an ellipse in the plane) bouncing on a floor, sometimes higher "
          "than it was dropped from: video analysis, the first instant of contact, a Hunt–Crossley "
          "contact model and phase diagrams of the rebound.",
  });
  s.add_paragraph(
      "Both studies measured motion by clicking points in video with Tracker and analysed it "
      "by hand in Excel and Wolfram Alpha. Where tribolab disagrees with a number printed in "
      "a study, the disagreement is checked by an independent method, and the study's error is "
      "recorded with the corrected value (the errata page at the end of this report, and "
      "docs/theory.md in the project).");

  s.add_subheading("Conventions and units");
  s.add_paragraph(
      "SI units throughout (m, s, kg, N); angles in radians except where a name ends in _deg "
      "or a column says °. g = 9.8 m/s², the studies' value, unless stated.");
  report::Table t;
  t.caption = "Symbols used in this report";
  t.header = {"symbol", "meaning", "unit"};
  t.rows = {
      {"x, y", "the incline study: x across the slope in the launch direction, y up the "
               "slope (the disc moves down, y < 0)", "m"},
      {"φ", "incline angle", "rad (φ_deg in degrees)"},
      {"μ", "kinetic friction coefficient", "—"},
      {"k = tan φ / μ", "decides the regime: k < 1 stops, k = 1 tends to a terminal speed, "
                        "k > 1 keeps accelerating", "—"},
      {"α = g μ cos φ, β = g sin φ", "friction and gravity accelerations along the incline",
       "m/s²"},
      {"x, y (bounce)", "the rugby-ball study: x horizontal, y up, floor at y = 0", "m"},
      {"θ, ω", "angle of the ball's major axis from the horizontal and spin, both "
               "counter-clockwise positive", "rad, rad/s"},
      {"a ≥ b", "semi-axes of the ball's elliptical section", "m"},
      {"e = −v_y,out / v_y,in", "coefficient of restitution of a bounce", "—"},
  };
  s.add_table(t);
  s.add_equation("Y(θ)^2 = a^2 sin^2 θ + b^2 cos^2 θ", "rugby-ball study, eq 20; docs/theory.md#bounce-geometry",
                 "Height of the centre of a resting ellipse above its lowest point (the "
                 "support distance) at orientation θ.");

  s.add_subheading("How to read this report");
  s.add_list({
      "A value written as x ± σ is the estimate x and its standard uncertainty σ "
      "(one standard deviation); the uncertainty is rounded to two significant digits and "
      "the value to the same decimal place.",
      "Every plot is interactive: hover for values, drag to zoom, double-click to reset, "
      "click a legend entry to hide a curve; the camera icon saves the plot as a PNG.",
      "The demo's reports (this one and film_tracking.html) share the plotting library, "
      "Plotly.js, in the file " + report::plotly_file_name() + " beside them: they open without a "
      "network connection as long as the folder stays together (the commands' --plotly file). "
      "A command's --report embeds the library by default (--plotly embed): one file to send.",
      "Equations cite their source: the study and its equation number, or docs/theory.md in "
      "the project for derivations and corrections.",
  });
  log << "  about: conventions and sources\n";
}

}  // namespace tribolab::app
