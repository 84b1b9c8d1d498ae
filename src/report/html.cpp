#include "report/html.hpp"

#include "io/atomic_file.hpp"
#include "report/embedded.hpp"
#include "report/format.hpp"
#include "report/plotly_json.hpp"
#include "report/units.hpp"

#include <filesystem>
#include <set>
#include <stdexcept>
#include <variant>

namespace tribolab::report {
namespace {

constexpr const char* kStyle = R"CSS(
:root { --ink: #1d2430; --muted: #5b6678; --rule: #d9dee7; --accent: #2c5d8f; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff;
  font: 16px/1.55 system-ui, -apple-system, "Segoe UI", "Noto Sans", "Noto Sans CJK SC", sans-serif; }
header, nav, main, footer { max-width: 1100px; margin: 0 auto; padding: 0 24px; }
header { padding-top: 28px; border-bottom: 1px solid var(--rule); }
h1 { font-size: 1.9rem; margin: 0 0 4px; }
.subtitle { color: var(--muted); margin: 0 0 16px; }
nav { padding-top: 12px; padding-bottom: 4px; }
nav h2 { font-size: 1rem; margin: 0 0 4px; color: var(--muted); }
nav ol { margin: 0; padding-left: 22px; columns: 2; }
a { color: var(--accent); }
section { border-top: 1px solid var(--rule); padding: 8px 0 16px; }
h2 { font-size: 1.45rem; margin: 16px 0 8px; }
h3 { font-size: 1.15rem; margin: 18px 0 6px; }
p { margin: 8px 0; max-width: 78ch; }
.equation { margin: 10px 0; padding: 8px 14px; background: #f6f8fb; border-left: 3px solid var(--accent); }
.equation .math { font-family: "Cambria Math", "STIX Two Math", "Latin Modern Math", Georgia, serif;
  font-size: 1.12rem; }
.equation .source { float: right; color: var(--muted); font-size: 0.9rem; }
.equation .note { margin: 4px 0 0; color: var(--muted); font-size: 0.92rem; }
table { border-collapse: collapse; margin: 12px 0; font-variant-numeric: tabular-nums; }
caption { caption-side: top; text-align: left; font-weight: 600; padding-bottom: 4px; }
th, td { border-bottom: 1px solid var(--rule); padding: 4px 12px; text-align: left; }
th { border-bottom: 2px solid var(--ink); }
td.num { text-align: right; white-space: nowrap; }
figure { margin: 16px 0; }
.tribolab-plot { width: 100%; }
figcaption { color: var(--muted); font-size: 0.95rem; }
.gallery { display: flex; flex-wrap: wrap; gap: 12px; margin: 16px 0 4px; }
.gallery figure { margin: 0; max-width: 100%; }
.gallery img { display: block; max-width: 100%; height: auto; border: 1px solid var(--rule); }
.gallery-caption { color: var(--muted); font-size: 0.95rem; margin-top: 0; }
footer { border-top: 1px solid var(--rule); color: var(--muted); font-size: 0.9rem; padding-top: 10px;
  padding-bottom: 30px; }
)CSS";

// Runs before Plotly.js loads, so errors while loading it are caught too.
constexpr const char* kErrorCapture = R"JS(
window.tribolabErrors = [];
window.tribolabShowStatus = function (text) {
  var el = document.getElementById('tribolab-status');
  if (!el) return;
  if (window.tribolabErrors.length) text = 'error: ' + window.tribolabErrors.join('; ');
  if (text !== undefined) el.textContent = text;
};
window.onerror = function (message, source, line) {
  window.tribolabErrors.push(String(message) + (line ? ' (line ' + line + ')' : ''));
  window.tribolabShowStatus();
  return false;
};
window.addEventListener('unhandledrejection', function (event) {
  window.tribolabErrors.push('unhandled rejection: ' + String(event.reason));
  window.tribolabShowStatus();
});
)JS";

// Draws every figure and decodes every embedded image; the status becomes "ok N" once all N
// Plotly.newPlot promises and every image's decode() resolved (an image that does not decode
// is an error naming it).
constexpr const char* kRender = R"JS(
(function () {
  var fail = function (e) {
    window.tribolabErrors.push(String(e && e.message ? e.message : e));
    window.tribolabShowStatus('');
  };
  try {
    if (typeof Plotly === 'undefined') throw new Error('Plotly.js did not load');
    var spec = JSON.parse(document.getElementById('tribolab-figures').textContent);
    var jobs = spec.figures.map(function (f) {
      return Plotly.newPlot(f.id, f.data, f.layout, f.config);
    });
    var images = Array.prototype.map.call(document.querySelectorAll('img.tribolab-image'), function (img, i) {
      return img.decode().catch(function () {
        throw new Error('image ' + (i + 1) + ' (' + img.alt + ') could not be decoded');
      });
    });
    Promise.all([Promise.all(jobs), Promise.all(images)]).then(function (done) {
      window.tribolabShowStatus('ok ' + done[0].length);
    }, fail);
  } catch (e) {
    fail(e);
  }
})();
)JS";

/// A unit in the report's notation: "^(...)" groups become "^{...}" ("N s/m^(n+1)").
std::string unit_notation(std::string u) {
  for (std::size_t p = 0; (p = u.find("^(", p)) != std::string::npos;) {
    const std::size_t close = u.find(')', p);
    if (close == std::string::npos) break;
    u[p + 1] = '{';
    u[close] = '}';
  }
  return u;
}

/// A cell holding a number, or a number with uncertainty ("0.634 ± 0.012", "(6.0 ± 1.2)×10⁵").
bool looks_numeric(const std::string& cell) {
  if (cell.empty()) return false;
  const char c = cell[0];
  const bool digit_after = cell.size() > 1 && cell[1] >= '0' && cell[1] <= '9';
  return (c >= '0' && c <= '9') || ((c == '-' || c == '+' || c == '(' || c == '.') && digit_after);
}

/// Columns whose cells are all numbers (or "—" for missing, with at least one number) are
/// right-aligned, so digits line up.
std::vector<bool> numeric_columns(const Table& t) {
  std::vector<bool> numeric(t.header.size(), false);
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    bool any = false, all = true;
    for (const auto& row : t.rows) {
      if (looks_numeric(row[c])) {
        any = true;
      } else if (row[c] != "—" && !row[c].empty()) {
        all = false;
      }
    }
    numeric[c] = any && all;
  }
  return numeric;
}

/// Where the page's plots come from, for the footer.
std::string plotly_origin(PlotlyMode mode, const std::string& src) {
  const std::string v = "Plotly.js " + std::string(plotly_version()) + " (MIT licence)";
  switch (mode) {
    case PlotlyMode::embed: return v + ", embedded in this file: the report works offline.";
    case PlotlyMode::cdn:
      return v + ", loaded from " + plotly_cdn_url() + ": the plots need a network connection.";
    case PlotlyMode::file:
      return v + ", read from the file " + src + " next to this one: keep them together; no network is needed.";
  }
  return v;
}

class Writer {
 public:
  Writer(std::string& out, PlotlyMode plotly, std::string script_src)
      : out_(out), plotly_(plotly), script_src_(std::move(script_src)) {}

  void write(const Report& r) {
    out_ += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out_ += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    out_ += "<meta name=\"generator\" content=\"tribolab " + std::string(tribolab_version()) +
            "\">\n";
    out_ += "<title>" + html_escape(r.title) + "</title>\n";
    out_ += "<style>" + std::string(kStyle) + "</style>\n";
    out_ += "<script>" + std::string(kErrorCapture) + "</script>\n";
    write_plotly_script_tag();
    out_ += "</head>\n<body>\n";

    out_ += "<header>\n<h1>" + html_escape(r.title) + "</h1>\n";
    if (!r.subtitle.empty()) out_ += "<p class=\"subtitle\">" + html_escape(r.subtitle) + "</p>\n";
    if (plotly_ != PlotlyMode::embed) {
      out_ += "<p class=\"subtitle\" id=\"tribolab-plotly-note\">Plots: " +
              html_escape(plotly_origin(plotly_, script_src_)) + "</p>\n";
    }
    out_ += "</header>\n";

    std::vector<std::string> ids;
    std::set<std::string> used;
    for (const Section& s : r.sections) {
      std::string id = slugify(s.heading);
      for (int k = 2; used.count(id) != 0; ++k) id = slugify(s.heading) + "-" + std::to_string(k);
      used.insert(id);
      ids.push_back(id);
    }
    if (!r.sections.empty()) {
      out_ += "<nav>\n<h2>Contents</h2>\n<ol>\n";
      for (std::size_t i = 0; i < r.sections.size(); ++i) {
        out_ += "<li><a href=\"#" + ids[i] + "\">" + html_escape(r.sections[i].heading) +
                "</a></li>\n";
      }
      out_ += "</ol>\n</nav>\n";
    }

    out_ += "<main>\n";
    for (std::size_t i = 0; i < r.sections.size(); ++i) write_section(r.sections[i], ids[i]);
    out_ += "</main>\n";

    out_ += "<footer>\n<p>Written by tribolab " + std::string(tribolab_version()) +
            ". Plots are drawn by " + html_escape(plotly_origin(plotly_, script_src_)) + " Hover over a "
            "plot for values, drag to zoom, double-click to reset; the camera icon saves a "
            "PNG. ± values are one standard uncertainty, rounded to two significant "
            "digits.</p>\n</footer>\n";
    out_ += "<div id=\"" + std::string(kStatusId) + "\" hidden>pending</div>\n";
    nlohmann::json spec = {{"figures", std::move(figures_)}};
    out_ += "<script type=\"application/json\" id=\"" + std::string(kFiguresId) + "\">" +
            json_for_script(spec) + "</script>\n";
    out_ += "<script>" + std::string(kRender) + "</script>\n</body>\n</html>\n";
  }

 private:
  void write_plotly_script_tag() {
    switch (plotly_) {
      case PlotlyMode::embed:
        out_ += "<script>/* Plotly.js " + std::string(plotly_version()) +
                ", MIT licence, embedded so this report needs no network */\n";
        out_ += script_safe(plotly_js());
        out_ += "\n</script>\n";
        return;
      case PlotlyMode::cdn:
        out_ += "<script src=\"" + html_escape(plotly_cdn_url()) + "\" integrity=\"" + plotly_integrity() +
                "\" crossorigin=\"anonymous\"></script>\n";
        return;
      case PlotlyMode::file:
        out_ += "<script src=\"" + html_escape(script_src_) + "\"></script>\n";
        return;
    }
  }

  void write_section(const Section& s, const std::string& id) {
    out_ += "<section id=\"" + id + "\">\n<h2>" + html_escape(s.heading) + "</h2>\n";
    for (const Block& b : s.blocks) std::visit([this](const auto& x) { block(x); }, b);
    out_ += "</section>\n";
  }

  void block(const Paragraph& p) { out_ += "<p>" + html_escape(p.text) + "</p>\n"; }

  void block(const Subheading& h) { out_ += "<h3>" + html_escape(h.text) + "</h3>\n"; }

  void block(const List& l) {
    out_ += "<ul>\n";
    for (const auto& item : l.items) out_ += "<li>" + html_escape(item) + "</li>\n";
    out_ += "</ul>\n";
  }

  void block(const Equation& e) {
    out_ += "<div class=\"equation\">";
    if (!e.source.empty()) out_ += "<span class=\"source\">" + html_escape(e.source) + "</span>";
    out_ += "<span class=\"math\">" + notation_html(e.text) + "</span>";
    if (!e.note.empty()) out_ += "<p class=\"note\">" + html_escape(e.note) + "</p>";
    out_ += "</div>\n";
  }

  void block(const Table& table) {
    // Every quantity/parameter table shows its units in a column of their own (units.hpp).
    Table with_units;
    if (is_parameter_table(table.header)) {
      with_units = table;
      with_units.header.insert(with_units.header.begin() + 1, "unit");
      for (auto& row : with_units.rows) {
        auto [label, unit] = split_unit(row[0]);
        row[0] = std::move(label);
        row.insert(row.begin() + 1, std::move(unit));
      }
    }
    const Table& t = is_parameter_table(table.header) ? with_units : table;
    out_ += "<table>\n";
    if (!t.caption.empty()) out_ += "<caption>" + html_escape(t.caption) + "</caption>\n";
    out_ += "<thead><tr>";
    for (const auto& h : t.header) out_ += "<th>" + notation_html(h) + "</th>";
    out_ += "</tr></thead>\n<tbody>\n";
    const std::vector<bool> numeric = numeric_columns(t);
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const auto& row = t.rows[r];
      const std::string href = r < t.links.size() ? t.links[r] : std::string();
      out_ += "<tr>";
      for (std::size_t c = 0; c < row.size(); ++c) {
        out_ += numeric[c] ? "<td class=\"num\">" : "<td>";
        if (c == 0 && !href.empty()) {
          out_ += "<a href=\"" + html_escape(href) + "\">" + html_escape(row[c]) + "</a></td>";
        } else {
          // A unit column's exponents as superscripts: "m/s^2", "N s/m^(n+1)" -> m^{n+1}.
          out_ += (c == 1 && &t == &with_units ? notation_html(unit_notation(row[c])) : html_escape(row[c])) + "</td>";
        }
      }
      out_ += "</tr>\n";
    }
    out_ += "</tbody>\n</table>\n";
  }

  void block(const Figure& f) {
    ++figure_number_;
    const std::string id = "figure-" + std::to_string(figure_number_);
    const std::string file_name = "tribolab-" + id + "-" + slugify(f.title, "plot");
    nlohmann::json fig = plotly_figure(f, file_name);
    fig["id"] = id;
    figures_.push_back(std::move(fig));
    out_ += "<figure>\n<div class=\"tribolab-plot\" id=\"" + id + "\" style=\"height:" +
            std::to_string(f.height_px) + "px\"></div>\n<figcaption>Figure " +
            std::to_string(figure_number_) + ". " +
            html_escape(f.caption.empty() ? f.title : f.caption) +
            "</figcaption>\n</figure>\n";
  }

  void block(const Gallery& g) {
    out_ += "<div class=\"gallery\">\n";
    for (const Image& im : g.images) {
      const std::string alt = im.alt.empty() ? im.caption : im.alt;
      out_ += "<figure><img class=\"tribolab-image\" alt=\"" + html_escape(alt) + "\" src=\"data:" +
              image_mime(im.data) + ";base64,";
      out_ += base64(std::string_view(reinterpret_cast<const char*>(im.data.data()), im.data.size()));
      out_ += "\">";
      if (!im.caption.empty()) out_ += "<figcaption>" + html_escape(im.caption) + "</figcaption>";
      out_ += "</figure>\n";
    }
    out_ += "</div>\n";
    if (!g.caption.empty()) out_ += "<p class=\"gallery-caption\">" + html_escape(g.caption) + "</p>\n";
  }

  std::string& out_;
  PlotlyMode plotly_;
  std::string script_src_;
  nlohmann::json figures_ = nlohmann::json::array();
  int figure_number_ = 0;
};

}  // namespace

std::string to_html(const Report& report, PlotlyMode plotly, const std::string& script_src) {
  if (auto e = report.validate(); !e.empty()) {
    throw std::invalid_argument("report '" + report.title + "': " + e);
  }
  const std::string src = script_src.empty() ? plotly_file_name() : script_src;
  if (plotly == PlotlyMode::file && !is_relative_link(src)) {
    throw std::invalid_argument("report '" + report.title + "': script '" + src + "' is not a relative path");
  }
  std::string out;
  out.reserve((plotly == PlotlyMode::embed ? plotly_js().size() : 0) + (1 << 16));
  Writer(out, plotly, src).write(report);
  return out;
}

void write_html(const Report& report, const std::string& path, PlotlyMode plotly, const std::string& script_dir) {
  namespace fs = std::filesystem;
  std::string src;
  if (plotly == PlotlyMode::file) {
    const fs::path page_dir = fs::absolute(fs::path(path)).parent_path().lexically_normal();
    const fs::path dir = script_dir.empty() ? page_dir : fs::absolute(fs::path(script_dir)).lexically_normal();
    src = (dir / plotly_file_name()).lexically_relative(page_dir).generic_string();
  }
  const std::string page = to_html(report, plotly, src);  // before opening: a bad report leaves no file
  if (plotly == PlotlyMode::file) {
    write_plotly_script(script_dir.empty() ? fs::path(path).parent_path().string() : script_dir);
  }
  io::AtomicFile file(path);
  file.stream().write(page.data(), static_cast<std::streamsize>(page.size()));
  file.commit();
}

}  // namespace tribolab::report
