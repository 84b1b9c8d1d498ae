// Writes a sample report that exercises every block and figure kind of the report writer,
// for the browser test (check_report.sh): 4 figures and a gallery of two images (a JPEG and a
// PNG encoded by OpenCV, which the page must decode). The data are simple closed forms
// (a free-fall parabola, a power law, a smooth function on a grid), not measurements.
//
//   report_sample OUT.html             the test report
//   report_sample OUT.html --defect=K  the test report with one defect a reader would see, which
//     check_report.sh must catch: K = caption ("Figure 1. Figure 2 (二)"), unit (a label with a
//     unit in its middle), subscript (ω_out for ω_{out}), internal (a test file's name)
//   report_sample OUT.html --readme    the report pictured in README.md (docs/img/report.png:
//     chromium --headless --no-sandbox --hide-scrollbars --virtual-time-budget=10000
//              --window-size=1100,1250 --screenshot=docs/img/report.png file://OUT.html)
#include "report/format.hpp"
#include "report/html.hpp"
#include "video/codec.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rpt = tribolab::report;

namespace {

rpt::Series series(std::string name, rpt::Mode mode, rpt::Dash dash = rpt::Dash::Solid) {
  rpt::Series s;
  s.name = std::move(name);
  s.mode = mode;
  s.dash = dash;
  return s;
}

rpt::Figure parabola_with_gap() {
  rpt::Figure f;
  f.title = "Free fall y(t) = y0 - g t²/2 with a gap";
  f.caption = "Markers with error bars (σ = 2 mm) and the model line; the NaN at t = 0.25 s "
              "must show as a gap in both.";
  f.x_axis = {"t (s)", false};
  f.y_axis = {"y (m)", false};
  rpt::Series data = series("points < & > \"quoted\"", rpt::Mode::Markers);
  rpt::Series model = series("model", rpt::Mode::Lines, rpt::Dash::Dash);
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.025 * i;
    const double y = i == 10 ? std::numeric_limits<double>::quiet_NaN() : 1.5 - 4.9 * t * t;
    data.x.push_back(t);
    data.y.push_back(y);
    data.y_error.push_back(0.002);
    model.x.push_back(t);
    model.y.push_back(y);
  }
  f.series = {data, model};
  return f;
}

rpt::Figure power_law_log_axes() {
  rpt::Figure f;
  f.title = "Power law on log axes";
  f.caption = "y = x^1.5 is a straight line of slope 1.5 on log–log axes.";
  f.x_axis = {"x (m)", true};
  f.y_axis = {"y (m^{1.5})", true};
  rpt::Series s = series("y = x^1.5", rpt::Mode::LinesMarkers);
  for (int i = 0; i <= 30; ++i) {
    const double x = std::pow(10.0, -2.0 + 0.1 * i);
    s.x.push_back(x);
    s.y.push_back(std::pow(x, 1.5));
  }
  f.series = {s};
  return f;
}

rpt::Figure heatmap_with_boundary() {
  rpt::Figure f;
  f.title = "Heat map with a contour overlay";
  f.caption = "z = 1 + 0.5 sin(x) cos(y) on a 41 × 31 grid, diverging scale centred on 1; the "
              "dashed curve is z = 1 (cos y = 0); the NaN cell at the corner is blank.";
  f.x_axis = {"x (rad)", false};
  f.y_axis = {"y (rad)", false};
  rpt::HeatMap h;
  for (int j = 0; j <= 40; ++j) h.x.push_back(-3.0 + 0.15 * j);
  for (int i = 0; i <= 30; ++i) h.y.push_back(-3.0 + 0.2 * i);
  for (double y : h.y) {
    std::vector<double> row;
    for (double x : h.x) row.push_back(1.0 + 0.5 * std::sin(x) * std::cos(y));
    h.z.push_back(row);
  }
  h.z[0][0] = std::numeric_limits<double>::quiet_NaN();
  h.colorbar_title = "z";
  h.colorscale = rpt::ColorScale::RdBu;
  h.z_mid = 1.0;
  f.heatmap = h;
  const double half_pi = std::acos(0.0);
  const double gap = std::numeric_limits<double>::quiet_NaN();
  rpt::Series boundary = series("z = 1", rpt::Mode::Lines, rpt::Dash::Dash);
  boundary.x = {-3.0, 3.0, gap, -3.0, 3.0};
  boundary.y = {-half_pi, -half_pi, gap, half_pi, half_pi};
  boundary.color = "black";
  f.series.push_back(boundary);
  return f;
}

rpt::Figure trajectory_equal_aspect() {
  rpt::Figure f;
  f.title = "Trajectory with equal axes";
  f.caption = "A circle of radius 0.2 m must look round (equal_aspect).";
  f.x_axis = {"x (m)", false};
  f.y_axis = {"y (m)", false};
  f.equal_aspect = true;
  f.height_px = 400;
  rpt::Series s = series("circle", rpt::Mode::Lines);
  for (int i = 0; i <= 64; ++i) {
    const double a = 2 * std::acos(-1.0) * i / 64;
    s.x.push_back(0.2 * std::cos(a));
    s.y.push_back(0.2 * std::sin(a));
  }
  f.series = {s};
  return f;
}

/// A picture drawn with OpenCV (a grey ramp with a red disc and its label), encoded as `ext`.
rpt::Image drawn_image(const std::string& ext, std::string caption) {
  cv::Mat img(120, 160, CV_8UC3);
  for (int i = 0; i < img.rows; ++i)
    for (int j = 0; j < img.cols; ++j) img.at<cv::Vec3b>(i, j) = cv::Vec3b::all(static_cast<unsigned char>(100 + j / 2));
  cv::circle(img, cv::Point(80, 60), 30, cv::Scalar(40, 40, 200), cv::FILLED, cv::LINE_AA);
  cv::putText(img, ext, cv::Point(8, 110), cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  rpt::Image im;
  im.data = tribolab::video::encode_image(ext, img);
  if (im.data.empty()) throw std::runtime_error("OpenCV cannot encode " + ext);
  im.caption = std::move(caption);
  return im;
}

rpt::Report sample() {
  rpt::Report r;
  r.title = "Sample <script>alert('x')</script> & \"report\"";
  r.subtitle = "Test of the tribolab report writer: every block kind, 4 figures.";
  auto& text = r.add_section("Text, equations and tables");
  text.add_paragraph("Plain text is escaped: <b>not bold</b> & 'quotes' stay as typed.");
  text.add_subheading("Equations");
  text.add_equation("k = tan φ / μ,  α = g μ cos φ,  β = g sin φ", "SPEC §1",
                    "The incline's parameters.");
  text.add_equation("Y(θ)^2 = a^2 sin^2 θ + b^2 cos^2 θ", "SPEC §3.1");
  text.add_list({"a list item", "another one with <angle brackets>"});
  rpt::Table t;
  t.caption = "Numbers with uncertainties";
  t.header = {"quantity", "value", "unit"};
  t.rows = {{"μ", rpt::format_uncertain(0.63427, 0.01234), ""},
            {"g", rpt::format_uncertain(9.81, 0.0996), "m/s^2"},
            {"N_A", rpt::format_uncertain(6.02214e23, 1.2e21), "1/mol"},
            {"missing", rpt::format_uncertain(std::nan(""), 0.1), ""}};
  text.add_table(t);
  auto& plots = r.add_section("Figures");
  plots.add_figure(parabola_with_gap());
  plots.add_figure(power_law_log_axes());
  plots.add_figure(heatmap_with_boundary());
  plots.add_figure(trajectory_equal_aspect());
  auto& images = r.add_section("Images");
  images.add_gallery({"Two images drawn by OpenCV, embedded as data URIs <not links>.",
                      {drawn_image(".jpg", "a JPEG & its caption"), drawn_image(".png", "a PNG")}});
  return r;
}

/// sample() with one defect of kind `kind` (see the file's header).
rpt::Report with_defect(const std::string& kind) {
  rpt::Report r = sample();
  auto& s = r.add_section("A defect");
  if (kind == "caption") {
    rpt::Figure f = parabola_with_gap();
    f.caption = "Figure 2 (二) of the study, redrawn";
    s.add_figure(std::move(f));
  } else if (kind == "unit") {
    rpt::Table t;
    t.caption = "Diagnostics";
    t.header = {"quantity", "value"};
    t.rows = {{"θ_c (deg), at t_c (s)", "52.09, 0.4317"}};
    s.add_table(std::move(t));
  } else if (kind == "subscript") {
    rpt::Figure f = heatmap_with_boundary();
    f.heatmap->colorbar_title = "ω_out (rad/s)";
    s.add_figure(std::move(f));
  } else if (kind == "internal") {
    s.add_paragraph("checked by test Foo in src/bounce/foo_test.cpp");
  } else {
    throw std::invalid_argument("unknown defect '" + kind + "'");
  }
  return r;
}

/// The picture in README.md (docs/img/report.png): the figures alone, under a plain title.
rpt::Report readme_picture() {
  rpt::Report r;
  r.title = "A tribolab report";
  r.subtitle = "Interactive plots: zoom, hover for values, save as PNG. Works offline.";
  auto& plots = r.add_section("Figures");
  plots.add_figure(heatmap_with_boundary());
  plots.add_figure(parabola_with_gap());
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 3 ? argv[2] : "";
  const bool readme = mode == "--readme", defect = mode.rfind("--defect=", 0) == 0;
  if (argc != 2 && !readme && !defect) {
    std::cerr << "usage: report_sample OUT.html [--readme | --defect=caption|unit|subscript|internal]\n";
    return 2;
  }
  try {
    const std::filesystem::path out(argv[1]);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    const rpt::Report r = readme ? readme_picture() : defect ? with_defect(mode.substr(9)) : sample();
    rpt::write_html(r, out.string());
    std::cout << out.string() << ": " << r.figure_count() << " figures\n";
  } catch (const std::exception& e) {
    std::cerr << "report_sample: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
