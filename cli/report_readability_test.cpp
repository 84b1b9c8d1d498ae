// The reports `tribolab demo` writes, read as a person would (issue 14, "Output a person can
// read"): every quantity/parameter table has a unit for each number (dimensionless marked as
// such), and every plot's axes span its data with a small margin (not Plotly's autorange,
// which widened the bounce-fit "measured vs fitted" plot to -10..13 for data in -2..3).
#include "cli_test_util.hpp"
#include "report/plotly_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

namespace tribolab::cli::testing {
namespace {

/// The demo's folder, written once for every test of this file.
const std::string& demo_dir() {
  static const std::string dir = [] {
    const std::string d = temp_dir("readability_demo");
    const auto r = run_tribolab("demo --out '" + d + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

/// The demo's two reports and those of commands the demo does not run as such.
std::vector<std::string> reports() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> r = {demo_dir() + "/report.html", demo_dir() + "/film_tracking.html"};
    const std::string d = demo_dir();
    for (const auto& [name, cmd] : std::vector<std::pair<std::string, std::string>>{
             {"bounce_simulate", "bounce simulate --vy -4 --omega 40"},
             {"bounce_drop", "bounce drop --height 1 --omega 20"},
             {"incline_mu_from_stop", "incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036 "
                                      "--sigma-phi-deg 0.1 --sigma-pos 0.002"},
             {"incline_simulate", "incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --out '" + d + "/s.csv'"},
             {"bounce_sweep", "bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --D 3000 --out '" + d + "/m.csv'"}}) {
      const std::string path = d + "/" + name + ".html";
      const auto res = run_tribolab(cmd + " --report '" + path + "' --plotly file");
      EXPECT_EQ(res.exit_code, 0) << cmd << "\n" << res.err;
      r.push_back(path);
    }
    return r;
  }();
  return all;
}

std::string strip_tags(const std::string& html) {
  std::string out;
  bool in_tag = false;
  for (char c : html) {
    if (c == '<') in_tag = true;
    else if (c == '>') in_tag = false;
    else if (!in_tag) out += c;
  }
  return out;
}

/// The contents of every `<tag ...>...</tag>` in `html`, in order (not nested). Plain string
/// search: libstdc++'s std::regex recurses once per character of a lazy `[\s\S]*?`, which
/// overflows the stack on a report's tables under AddressSanitizer.
std::vector<std::string> elements(const std::string& html, const std::string& tag) {
  std::vector<std::string> out;
  const std::string open = "<" + tag, close = "</" + tag + ">";
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at)) {
    const char next = at + open.size() < html.size() ? html[at + open.size()] : '\0';
    if (next != '>' && next != ' ') {  // another tag with this prefix (<th> vs <thead>)
      at += open.size();
      continue;
    }
    const std::size_t begin = html.find('>', at);
    const std::size_t end = begin == std::string::npos ? std::string::npos : html.find(close, begin);
    if (end == std::string::npos) break;
    out.push_back(html.substr(begin + 1, end - begin - 1));
    at = end + close.size();
  }
  return out;
}

std::vector<std::string> cells(const std::string& row, const char* tag) {
  std::vector<std::string> out;
  for (const std::string& e : elements(row, tag)) out.push_back(strip_tags(e));
  return out;
}

bool numeric(const std::string& cell) {
  return !cell.empty() && (std::isdigit(static_cast<unsigned char>(cell[0])) ||
                           ((cell[0] == '-' || cell[0] == '(' || cell[0] == '.') && cell.size() > 1 &&
                            std::isdigit(static_cast<unsigned char>(cell[1]))) ||
                           cell.rfind("−", 0) == 0);
}

TEST(DemoReports, EveryParameterTableHasAUnitForEachNumber) {
  int tables = 0;
  for (const std::string& path : reports()) {
    const std::string html = slurp(path);
    for (const std::string& t : elements(html, "table")) {
      const std::vector<std::string> header = cells(t, "th");
      if (header.empty() || (header[0] != "quantity" && header[0] != "parameter")) continue;
      const std::string caption = cells(t, "caption").empty() ? "" : cells(t, "caption")[0];
      ++tables;
      ASSERT_GE(header.size(), 3u) << caption;
      EXPECT_EQ(header[1], "unit") << path << ": " << caption;
      const std::string body = t.substr(t.find("<tbody>"));
      for (const std::string& row : elements(body, "tr")) {
        const std::vector<std::string> c = cells(row, "td");
        ASSERT_EQ(c.size(), header.size());
        const bool any_number = std::any_of(c.begin() + 2, c.end(), numeric);
        if (any_number) {
          EXPECT_FALSE(c[1].empty()) << path << ": table '" << caption << "', row '" << c[0] << "'";
        }
      }
    }
  }
  EXPECT_GE(tables, 10);  // the demo has many: the loop above did run
}

/// Finite values of a JSON array (nested one level for heat-map z), min and max.
void extent(const nlohmann::json& a, double& lo, double& hi) {
  for (const auto& v : a) {
    if (v.is_array()) {
      extent(v, lo, hi);
    } else if (v.is_number()) {
      lo = std::min(lo, v.get<double>());
      hi = std::max(hi, v.get<double>());
    }
  }
}

TEST(DemoReports, EveryAxisSpansItsDataWithASmallMargin) {
  int axes = 0;
  for (const std::string& path : reports()) {
    const std::string html = slurp(path);
    const std::string open = "id=\"tribolab-figures\">";
    const auto b = html.find(open);
    ASSERT_NE(b, std::string::npos);
    const auto e = html.find("</script>", b);
    const auto spec = nlohmann::json::parse(html.substr(b + open.size(), e - b - open.size()));
    for (const auto& fig : spec["figures"]) {
      const std::string title = fig["layout"]["title"]["text"];
      for (const char* axis : {"x", "y"}) {
        const auto& layout_axis = fig["layout"][std::string(axis) + "axis"];
        double lo = INFINITY, hi = -INFINITY;
        bool heat = false;
        for (const auto& trace : fig["data"]) {
          heat |= trace["type"] == "heatmap";
          extent(trace[axis], lo, hi);
          for (const char* err : {"error_x", "error_y"}) {
            if (!trace.contains(err) || std::string(err).back() != axis[0]) continue;
            const auto& v = trace[axis];
            const auto& d = trace[err]["array"];
            for (std::size_t i = 0; i < v.size() && i < d.size(); ++i)
              if (v[i].is_number() && d[i].is_number()) {
                lo = std::min(lo, v[i].get<double>() - d[i].get<double>());
                hi = std::max(hi, v[i].get<double>() + d[i].get<double>());
              }
          }
        }
        if (!(lo <= hi)) continue;  // nothing drawn
        if (layout_axis["type"] == "log") continue;  // ranges in log10 units; covered by report_tests
        ASSERT_TRUE(layout_axis.contains("range")) << path << ": '" << title << "' " << axis;
        const double r0 = layout_axis["range"][0], r1 = layout_axis["range"][1];
        const double span = hi - lo;
        // A heat map extends half a cell beyond its outer centres (at most half the span for
        // a 2-cell axis); otherwise 4 % margins (kAxisMargin), checked against 10 %.
        const double slack = heat ? 0.5 * span : 0.1 * (span > 0 ? span : std::max(std::abs(lo), 1.0));
        EXPECT_LE(r0, lo + 1e-9 * std::max(1.0, std::abs(lo))) << path << ": '" << title << "' " << axis;
        EXPECT_GE(r1, hi - 1e-9 * std::max(1.0, std::abs(hi))) << path << ": '" << title << "' " << axis;
        EXPECT_GE(r0, lo - slack) << path << ": '" << title << "' " << axis << " data " << lo << ".." << hi;
        EXPECT_LE(r1, hi + slack) << path << ": '" << title << "' " << axis << " data " << lo << ".." << hi;
        if (fig["layout"]["yaxis"].contains("scaleanchor")) {
          EXPECT_EQ(layout_axis["constrain"], "domain") << title;  // 1:1 by shrinking the plot, not the range
        }
        ++axes;
      }
    }
  }
  EXPECT_GE(axes, 50);
}

}  // namespace
}  // namespace tribolab::cli::testing
