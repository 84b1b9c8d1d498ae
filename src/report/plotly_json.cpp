#include "report/plotly_json.hpp"

#include <algorithm>

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

const char* colorscale_name(ColorScale c) {
  switch (c) {
    case ColorScale::Viridis: return "Viridis";
    case ColorScale::Cividis: return "Cividis";
    case ColorScale::RdBu: return "RdBu";
  }
  return "Viridis";
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
  for (const auto& row : h.z) z.push_back(numbers(row));
  json t = {{"type", "heatmap"},
            {"x", numbers(h.x)},
            {"y", numbers(h.y)},
            {"z", std::move(z)},
            {"colorscale", colorscale_name(h.colorscale)},
            {"reversescale", h.colorscale == ColorScale::RdBu},  // red low, blue high
            {"showlegend", false},
            {"hoverongaps", false},
            {"colorbar", {{"title", {{"text", notation_html(h.colorbar_title)}, {"side", "right"}}}}}};
  if (h.z_mid) t["zmid"] = *h.z_mid;
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

}  // namespace

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
  if (figure.equal_aspect) {
    layout["yaxis"]["scaleanchor"] = "x";
    layout["yaxis"]["scaleratio"] = 1;
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
