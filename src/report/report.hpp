// The content of an HTML report, as plain structs: a Report holds Sections, a Section holds
// an ordered list of blocks (paragraphs, equations, tables, figures, ...). Nothing here knows
// about HTML; html.hpp turns a Report into one self-contained, offline file.
//
// All text is plain text: the writer escapes it, so a title may safely contain "<", "&" or
// quotes. Physical numbers go into figures as doubles (written with full precision, NaN as a
// gap) and into tables as text made by format.hpp (e.g. "0.634 ± 0.012").
#pragma once

#include <cmath>
#include <deque>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace tribolab::report {

/// A paragraph of plain text (escaped when written; blank lines are not interpreted).
struct Paragraph {
  std::string text;
};

/// A minor heading inside a section (written as <h3>).
struct Subheading {
  std::string text;
};

/// A bulleted list of plain-text items.
struct List {
  std::vector<std::string> items;
};

/// An equation shown as readable text. `text` uses a small notation: `_` starts a subscript
/// and `^` a superscript, each applying to the next character or to a `{...}` group
/// ("v_{x0} = v_0 cos^2 phi", "e^{-k t}"); Greek names are not translated, write the symbol
/// ("φ", "μ"). `source` says where it comes from, e.g. "seed 000, eq 十A" or
/// "docs/theory.md#stopping-point"; `note` is an optional plain-text explanation.
struct Equation {
  std::string text;
  std::string source;
  std::string note;
};

/// A table of text cells. Every row must have as many cells as the header. Use
/// format_uncertain()/format_value() from format.hpp for numbers.
struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// Optional: one link per row (empty string: none), made on the row's first cell, e.g.
  /// to a run's own report beside this one. Must be a relative path of letters, digits and
  /// `. _ - / %` (no scheme, no leading '/'), so a report never points off the disc.
  std::vector<std::string> links = {};
};

/// True when `href` is a link Table::links accepts (a non-empty relative path of letters,
/// digits and . _ - / %, not starting with '/').
bool is_relative_link(const std::string& href);

/// How a series is drawn.
enum class Mode { Markers, Lines, LinesMarkers };

/// Line style of a series drawn with lines.
enum class Dash { Solid, Dash, Dot };

/// One x–y series of a figure. NaN in x or y leaves a gap (the line is broken there), so a
/// curve of several pieces (e.g. both branches of the e = 1 boundary) is one series.
/// Error bars are one standard uncertainty; leave them empty for none, else give one value
/// per point (NaN = no bar at that point).
struct Series {
  std::string name;
  std::vector<double> x, y;
  std::vector<double> x_error, y_error;
  Mode mode = Mode::Markers;
  Dash dash = Dash::Solid;
  std::string color;  ///< CSS colour ("black", "#1f77b4"); empty = Plotly's colour cycle
};

/// Colour scales offered for heat maps (Plotly's names).
enum class ColorScale {
  Viridis,  ///< perceptually uniform, the default
  Cividis,  ///< uniform and readable with colour-vision deficiency
  RdBu,     ///< diverging red (low) – white – blue (high); with HeatMap::z_mid (1 for restitution)
  PuOr,     ///< diverging orange (low) – white – purple (high), e.g. a signed spin with z_mid 0
};

/// A heat map z(x, y) on a rectangular grid: z[i][j] is the value at (x[j], y[i]), so z has
/// y.size() rows of x.size() values. NaN cells are left blank.
struct HeatMap {
  std::vector<double> x, y;
  std::vector<std::vector<double>> z;
  std::string colorbar_title;  ///< with unit, e.g. "e" or "v_y,out (m/s)"
  ColorScale colorscale = ColorScale::Viridis;
  /// Value at the neutral (white) colour of a diverging scale. The colour bar spans the data
  /// (min to max of z), not a range made symmetric about z_mid: one unit of z is the same
  /// step of colour on both sides, and a side the data do not reach is not drawn.
  std::optional<double> z_mid;
};

/// One axis: title with its unit, e.g. "t (s)", and linear or logarithmic scale.
struct Axis {
  std::string title;
  bool log = false;
};

/// An interactive figure (zoom, hover, export to PNG from Plotly's mode bar): optionally a
/// heat map underneath, and any number of series drawn over it (e.g. the e = 1 boundary).
struct Figure {
  std::string title;
  std::string caption;  ///< plain text shown under the plot ("Figure N. caption")
  Axis x_axis, y_axis;
  std::optional<HeatMap> heatmap;
  std::vector<Series> series;
  bool equal_aspect = false;  ///< one metre on x as long as on y (trajectories)
  int height_px = 450;        ///< plot height in CSS pixels; typical 350–600

  /// Empty when the figure can be drawn; else what is wrong (sizes that do not match, a
  /// non-positive value on a log axis is allowed: Plotly leaves it out).
  std::string validate() const;
};

/// An encoded still image, e.g. a video frame with the tracks drawn (video::encode_image's output).
/// It is embedded in the page as a base64 data URI, so the report stays one offline file.
struct Image {
  std::vector<unsigned char> data;  ///< the bytes of a JPEG or PNG file
  std::string caption;              ///< plain text under the image, e.g. "frame 12, t = 0.050 s"
  std::string alt;                  ///< read out in place of the image; empty: the caption
};

/// The MIME type of encoded image bytes from their signature: "image/jpeg" (FF D8 FF),
/// "image/png" (89 50 4E 47 0D 0A 1A 0A), or "" for anything else.
std::string image_mime(const std::vector<unsigned char>& data);

/// Images side by side, wrapping to the page width (e.g. thumbnails of video frames). Each
/// keeps its natural size up to the page width; the page checks that every one decodes.
struct Gallery {
  std::string caption;  ///< plain text under the whole group; may be empty
  std::vector<Image> images;
};

/// One block of a section, in reading order.
using Block = std::variant<Paragraph, Subheading, List, Equation, Table, Figure, Gallery>;

/// A section of the report: a heading (<h2>, listed in the table of contents) and blocks.
struct Section {
  std::string heading;
  std::vector<Block> blocks;

  Section& add_paragraph(std::string text);
  Section& add_subheading(std::string text);
  Section& add_list(std::vector<std::string> items);
  Section& add_equation(std::string text, std::string source, std::string note = {});
  Section& add_table(Table table);
  Section& add_figure(Figure figure);
  Section& add_gallery(Gallery gallery);

  /// Number of figures in this section.
  int figure_count() const;
};

/// A whole report: title, an optional plain-text subtitle line, and sections.
struct Report {
  std::string title;
  std::string subtitle;
  std::deque<Section> sections;  ///< a deque: references from add_section() stay valid

  /// Appends an empty section and returns it for filling; the reference stays valid when
  /// more sections are added.
  Section& add_section(std::string heading);

  /// Number of figures in the report (= plots the page draws).
  int figure_count() const;
  /// Empty when the report can be written; else the first problem, naming the figure, table
  /// or gallery ("section 'Incline', figure 'x-t': series 'data': x has 10 values, y has 9";
  /// "section 'Frames', gallery 'g', image 2 ('frame 4'): not a JPEG or PNG file").
  std::string validate() const;
};

}  // namespace tribolab::report
