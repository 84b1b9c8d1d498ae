#include "io/track_csv.hpp"

#include "io/text.hpp"
#include "io/track_text.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace tribolab::io {

using namespace tracktext;

namespace {

std::optional<Line> first_line(const std::vector<Line>& ls, std::size_t& i) {
  while (i < ls.size() && (trim(ls[i].text).empty() || trim(ls[i].text).front() == '#')) ++i;
  if (i >= ls.size()) return std::nullopt;
  return ls[i];
}

char tidy_delimiter(std::string_view header) {
  for (char d : {'\t', ';', ','}) {
    if (header.find(d) != std::string_view::npos) return d;
  }
  return ',';
}

}  // namespace

bool looks_like_tidy_csv(std::string_view text) {
  const auto ls = lines(text.substr(0, 4096));
  std::size_t i = 0;
  const auto l = first_line(ls, i);
  if (!l) return false;
  const auto cs = cells(l->text, tidy_delimiter(l->text));
  return !cs.empty() && column_name(cs.front()).base == "track";
}

track::TrackSet parse_tidy_csv(std::string_view text, const std::string& source) {
  const auto ls = lines(text);
  std::size_t i = 0;
  const auto header = first_line(ls, i);
  if (!header) throw InputError(source, "no data: the file holds only blank or # lines");
  const char d = tidy_delimiter(header->text);
  const auto head = cells(header->text, d);
  std::size_t ncols = head.size();
  while (ncols > 0 && head[ncols - 1].empty()) --ncols;  // a trailing delimiter
  std::map<std::string, std::size_t> col;
  std::string length_unit;
  double tscale = 1;
  for (std::size_t k = 0; k < head.size(); ++k) {
    const ColumnName c = column_name(head[k]);
    if (c.base.empty()) continue;
    col.emplace(c.base, k);
    if ((c.base == "x" || c.base == "y") && !c.unit.empty()) {
      if (!length_unit.empty() && length_unit != c.unit) {
        throw InputError(at(source, header->number), "conflicting length units in the header");
      }
      length_unit = c.unit;
    }
    if (c.base == "t") {
      const auto s = seconds_per_unit(c.unit);
      if (!s) throw InputError(at(source, header->number), "unknown time unit '" + c.unit.substr(0, 20) + "'");
      tscale = *s;
    }
  }
  for (const char* need : {"track", "frame", "t", "x", "y"}) {
    if (!col.count(need)) {
      throw InputError(at(source, header->number),
                       std::string("missing column '") + need + "' (expected track,frame,t,x,y)");
    }
  }
  track::TrackSet set;
  set.source = source;
  set.format = "tidy_csv";
  if (!length_unit.empty()) set.file_length_unit = length_unit;
  std::map<std::string, std::size_t> index;
  std::vector<std::vector<std::pair<track::TrackPoint, int>>> rows;  // point and its line
  const bool decimal_comma = d != ',';
  std::size_t lost_rows = 0;
  for (++i; i < ls.size(); ++i) {
    const Line& line = ls[i];
    const std::string_view tl = trim(line.text);
    if (tl.empty() || tl.front() == '#') continue;
    const std::string where = at(source, line.number);
    const auto cs = cells(line.text, d);
    // A cell beyond the header's columns: the row is shifted (a decimal comma in a
    // comma-separated file, a stray delimiter), never read as if aligned (as the export reader).
    for (std::size_t k = ncols; k < cs.size(); ++k) {
      if (!cs[k].empty()) {
        throw InputError(where, std::to_string(cs.size()) + " cells but the header has " +
                                    std::to_string(ncols) + " columns (a decimal comma in a comma-separated file?)");
      }
    }
    auto cell = [&](const char* name) {
      const std::size_t k = col.at(name);
      if (k >= cs.size()) throw InputError(where, std::string("missing value for '") + name + "'");
      return cs[k];
    };
    const std::string name(cell("track"));
    if (name.empty()) throw InputError(where, "empty track name");
    if (auto e = name_text_problem(name); !e.empty()) throw InputError(where, "the track name " + e);
    const double f = parse_double(cell("frame"), where + " (frame)", decimal_comma);
    if (f != std::floor(f) || f < 0 || f > 1e8) {
      throw InputError(where, "frame must be a whole number from 0 to 1e8, got " + format_number(f));
    }
    if (trim(cell("x")).empty() && trim(cell("y")).empty()) {
      ++lost_rows;  // `track video` writes a lost object's frames with empty positions
      continue;
    }
    track::TrackPoint p;
    p.frame = static_cast<int>(f);
    p.t = check_track_value(parse_double(cell("t"), where + " (t)", decimal_comma), kMaxTrackTime, where, "t") * tscale;
    p.x = check_track_value(parse_double(cell("x"), where + " (x)", decimal_comma), kMaxTrackCoordinate, where, "x");
    p.y = check_track_value(parse_double(cell("y"), where + " (y)", decimal_comma), kMaxTrackCoordinate, where, "y");
    auto [it, fresh] = index.emplace(name, set.tracks.size());
    if (fresh) {
      set.tracks.push_back({name, {}});
      rows.emplace_back();
    }
    rows[it->second].emplace_back(p, line.number);
  }
  if (lost_rows > 0) {
    set.warnings.push_back(std::to_string(lost_rows) +
                           " row(s) with empty x and y (frames where the tracker lost its object) "
                           "were left out");
  }
  for (std::size_t k = 0; k < rows.size(); ++k) {
    auto& r = rows[k];
    std::stable_sort(r.begin(), r.end(),
                     [](const auto& a, const auto& b) { return a.first.frame < b.first.frame; });
    for (std::size_t j = 0; j < r.size(); ++j) {
      if (j > 0 && r[j].first.frame == r[j - 1].first.frame) {
        throw InputError(at(source, r[j].second), "track '" + set.tracks[k].name + "': frame " +
                                                      std::to_string(r[j].first.frame) +
                                                      " appears twice");
      }
      if (j > 0 && !(r[j].first.t > r[j - 1].first.t)) {
        throw InputError(at(source, r[j].second),
                         "track '" + set.tracks[k].name + "': time does not increase with frame");
      }
      set.tracks[k].points.push_back(r[j].first);
    }
  }
  return set;
}

namespace {
std::string cell(double v) { return std::isfinite(v) ? exact(v) : ""; }
}  // namespace

void write_tidy_csv(std::ostream& out, const track::TrackSet& set) {
  out << "track,frame,t,x,y\n";
  for (const auto& tr : set.tracks) {
    const std::string name = csv_quote(tr.name);
    for (const auto& p : tr.points) {
      out << name << ',' << p.frame << ',' << exact(p.t) << ',' << exact(p.x) << ',' << exact(p.y)
          << '\n';
    }
  }
}

void write_kinematics_csv(std::ostream& out, const track::Kinematics& k, bool sigmas) {
  out << "t,x,y,vx,vy,ax,ay";
  if (sigmas) out << ",sigma_vx,sigma_vy,sigma_ax,sigma_ay";
  out << '\n';
  for (const auto& r : k.rows) {
    out << cell(r.t) << ',' << cell(r.x) << ',' << cell(r.y) << ',' << cell(r.vx) << ','
        << cell(r.vy) << ',' << cell(r.ax) << ',' << cell(r.ay);
    if (sigmas) {
      out << ',' << cell(r.sigma_vx) << ',' << cell(r.sigma_vy) << ',' << cell(r.sigma_ax) << ','
          << cell(r.sigma_ay);
    }
    out << '\n';
  }
}

}  // namespace tribolab::io
