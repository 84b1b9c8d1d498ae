#include "report/plotly_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "report/format.hpp"

namespace tribolab::report {
namespace {

using nlohmann::json;

/// Doubles as JSON numbers; NaN and infinities are dumped as null, which Plotly draws as a
/// gap (connectgaps is false) or a blank heat-map cell.
json numbers(const std::vector<double>& v) { return json(v); }

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::Markers: return "markers";
    case Mode::Lines: return "lines";
    case Mode::LinesMarkers: return "lines+markers";
  }
  return "markers";
}

const char* dash_name(Dash d) {
  switch (d) {
    case Dash::Solid: return "solid";
    case Dash::Dash: return "dash";
    case Dash::Dot: return "dot";
  }
  return "solid";
}

/// ColorBrewer's 11-class diverging schemes, low to high, the sixth the neutral colour.
using Scheme = std::array<std::array<int, 3>, 11>;
constexpr Scheme kRdBu = {{{103, 0, 31}, {178, 24, 43}, {214, 96, 77}, {244, 165, 130}, {253, 219, 199},
                           {247, 247, 247}, {209, 229, 240}, {146, 197, 222}, {67, 147, 195}, {33, 102, 172},
                           {5, 48, 97}}};
constexpr Scheme kPuOr = {{{127, 59, 8}, {179, 88, 6}, {224, 130, 20}, {253, 184, 99}, {254, 224, 182},
                           {247, 247, 247}, {216, 218, 235}, {178, 171, 210}, {128, 115, 172}, {84, 39, 136},
                           {45, 0, 75}}};

/// The scheme's colour at t in [0, 1] (linear in RGB between its stops).
std::string scheme_rgb(const Scheme& s, double t) {
  t = std::clamp(t, 0.0, 1.0) * 10;
  const int i = std::min(static_cast<int>(t), 9);
  const double f = t - i;
  std::string out = "rgb(";
  for (int c = 0; c < 3; ++c) {
    out += std::to_string(static_cast<int>(std::lround(s[i][c] + f * (s[i + 1][c] - s[i][c]))));
    out += c < 2 ? "," : ")";
  }
  return out;
}

json colorscale_json(const std::vector<ColorStop>& stops) {
  if (stops.size() == 1 && stops[0].rgb.empty()) return stops[0].position == 0 ? "Viridis" : "Cividis";
  json a = json::array();
  for (const ColorStop& s : stops) a.push_back({s.position, s.rgb});
  return a;
}

json error_bars(const std::vector<double>& e) {
  return {{"type", "data"}, {"array", numbers(e)}, {"visible", true}, {"thickness", 1}};
}

json series_trace(const Series& s) {
  json t = {{"type", "scatter"},
            {"name", escape_text(s.name)},
            {"x", numbers(s.x)},
            {"y", numbers(s.y)},
            {"mode", mode_name(s.mode)},
            {"connectgaps", false}};
  if (s.mode != Mode::Markers) t["line"] = {{"dash", dash_name(s.dash)}, {"width", 2}};
  if (s.mode != Mode::Lines) t["marker"] = {{"size", 6}};
  if (!s.color.empty()) {
    if (t.contains("line")) t["line"]["color"] = s.color;
    if (t.contains("marker")) t["marker"]["color"] = s.color;
  }
  if (!s.x_error.empty()) t["error_x"] = error_bars(s.x_error);
  if (!s.y_error.empty()) t["error_y"] = error_bars(s.y_error);
  return t;
}

json heatmap_trace(const HeatMap& h) {
  json z = json::array();
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  for (const auto& row : h.z) {
    z.push_back(numbers(row));
    for (double v : row)
      if (std::isfinite(v)) {
        zmin = std::min(zmin, v);
        zmax = std::max(zmax, v);
      }
  }
  json t = {{"type", "heatmap"},
            {"x", numbers(h.x)},
            {"y", numbers(h.y)},
            {"z", std::move(z)},
            {"showlegend", false},
            {"hoverongaps", false},
            {"colorbar", {{"title", {{"text", notation_html(h.colorbar_title)}, {"side", "right"}}}}}};
  if (zmin <= zmax) {
    t["colorscale"] = colorscale_json(heatmap_colorscale(h, zmin, zmax));
    t["zmin"] = zmin;
    t["zmax"] = zmax;
    t["zauto"] = false;
  } else {
    t["colorscale"] = "Viridis";  // no finite value: nothing is coloured
  }
  return t;
}

json axis(const Axis& a) {
  return {{"title", {{"text", notation_html(a.title)}}},
          {"type", a.log ? "log" : "linear"},
          {"exponentformat", "power"},
          {"showline", true},
          {"mirror", true},
          {"ticks", "outside"},
          {"zeroline", false},
          {"automargin", true}};
}

/// The extent of a set of values along one axis (log: of log10 of the positive ones).
struct Extent {
  bool log = false;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v) || (log && v <= 0)) return;
    const double u = log ? std::log10(v) : v;
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  bool empty() const { return !(lo <= hi); }
};

void add_series(Extent& e, const std::vector<double>& v, const std::vector<double>& err) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double d = i < err.size() && std::isfinite(err[i]) ? std::abs(err[i]) : 0.0;
    e.add(v[i] - d);
    e.add(v[i] + d);
  }
}

/// Heat-map cell edges along one axis: half a spacing beyond the first and last centres.
void add_cells(Extent& e, const std::vector<double>& c) {
  std::vector<double> v;
  for (double x : c)
    if (std::isfinite(x)) v.push_back(x);
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  if (v.size() == 1) {
    e.add(v[0]);
    return;
  }
  e.add(v.front() - (v[1] - v[0]) / 2);
  e.add(v.back() + (v.back() - v[v.size() - 2]) / 2);
}

}  // namespace

std::vector<ColorStop> heatmap_colorscale(const HeatMap& h, double zmin, double zmax) {
  if (h.colorscale == ColorScale::Viridis) return {{0, ""}};
  if (h.colorscale == ColorScale::Cividis) return {{1, ""}};
  const Scheme& scheme = h.colorscale == ColorScale::RdBu ? kRdBu : kPuOr;
  const double mid = h.z_mid.value_or((zmin + zmax) / 2);
  // t(z): the scheme's position of z, 0.5 at mid, the same scale on both sides, the farther
  // data extreme at 0 or 1; the colour bar shows t(zmin)..t(zmax) over zmin..zmax.
  const double half = std::max(std::abs(zmin - mid), std::abs(zmax - mid));
  auto t = [&](double v) { return half > 0 ? 0.5 + 0.5 * (v - mid) / half : 0.5; };
  const double t0 = t(zmin), t1 = t(zmax);
  std::vector<double> ts = {t0};
  for (int k = 1; k < 10; ++k)
    if (k / 10.0 > t0 && k / 10.0 < t1) ts.push_back(k / 10.0);  // the scheme's own stops inside
  ts.push_back(t1);
  std::vector<ColorStop> stops;
  for (double x : ts) stops.push_back({t1 > t0 ? (x - t0) / (t1 - t0) : 0.0, scheme_rgb(scheme, x)});
  if (stops.size() == 2 && t1 == t0) stops.back().position = 1;  // constant data: one colour
  return stops;
}

std::optional<std::pair<double, double>> axis_range(const Figure& figure, bool y) {
  const bool log = y ? figure.y_axis.log : figure.x_axis.log;
  Extent data{log}, cells{log};
  for (const Series& s : figure.series) add_series(data, y ? s.y : s.x, y ? s.y_error : s.x_error);
  if (figure.heatmap) add_cells(cells, y ? figure.heatmap->y : figure.heatmap->x);
  if (data.empty() && cells.empty()) return std::nullopt;
  double lo = data.lo, hi = data.hi;
  if (!data.empty()) {
    double pad = kAxisMargin * (hi - lo);
    if (pad == 0) pad = lo == 0 ? 1.0 : 0.05 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  // Heat-map cells fill the plot to their edges; series that reach beyond them get the margin.
  if (!cells.empty()) {
    lo = data.empty() || data.lo >= cells.lo ? cells.lo : lo;
    hi = data.empty() || data.hi <= cells.hi ? cells.hi : hi;
  }
  return std::make_pair(lo, hi);
}

json plotly_figure(const Figure& figure, const std::string& file_name) {
  json data = json::array();
  if (figure.heatmap) data.push_back(heatmap_trace(*figure.heatmap));
  for (const Series& s : figure.series) data.push_back(series_trace(s));

  json layout = {{"title", {{"text", escape_text(figure.title)}}},
                 {"xaxis", axis(figure.x_axis)},
                 {"yaxis", axis(figure.y_axis)},
                 {"height", figure.height_px},
                 {"hovermode", "closest"},
                 {"margin", {{"t", 50}, {"r", 20}, {"b", 50}, {"l", 60}}},
                 // Legend under the x axis's tick labels and title (about 55 px under the
                 // plot area, whatever the height); Plotly widens the bottom margin for it.
                 {"legend", {{"orientation", "h"}, {"yanchor", "top"},
                             {"y", -58.0 / std::max(figure.height_px - 100, 100)}}}};
  for (const bool y : {false, true}) {
    if (const auto r = axis_range(figure, y)) layout[y ? "yaxis" : "xaxis"]["range"] = {r->first, r->second};
  }
  if (figure.equal_aspect) {
    layout["yaxis"]["scaleanchor"] = "x";
    layout["yaxis"]["scaleratio"] = 1;
    // Keep both ranges (the data's) and shrink the plot area to one metre per metre.
    layout["xaxis"]["constrain"] = "domain";
    layout["yaxis"]["constrain"] = "domain";
  }
  // Offline: Plotly's "share chart" button would upload the data to plotlyServerURL;
  // it is removed and the URL emptied. Every remaining button works locally.
  json config = {{"responsive", true},
                 {"displaylogo", false},
                 {"displayModeBar", true},
                 {"showSendToCloud", false},
                 {"plotlyServerURL", ""},
                 {"showTips", false},
                 {"modeBarButtonsToRemove", {"select2d", "lasso2d", "sendChartToCloud"}},
                 {"toImageButtonOptions", {{"format", "png"}, {"filename", file_name}, {"scale", 2}}}};
  return {{"data", std::move(data)}, {"layout", std::move(layout)}, {"config", std::move(config)}};
}

}  // namespace tribolab::report
