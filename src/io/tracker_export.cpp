#include "io/tracker_export.hpp"

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

struct Group {
  std::string name;
  std::size_t x = 0, y = 0;
  std::optional<std::size_t> frame;
  // ordering checks
  long long last_frame = -1;
  double last_t = 0;
  bool any = false;
};

bool is_header(const std::vector<std::string_view>& cs) {
  bool t = false, x = false, y = false;
  for (auto c : cs) {
    const ColumnName n = column_name(c);
    t = t || is_time_name(n);
    x = x || n.base == "x";
    y = y || n.base == "y";
  }
  return t && x && y && cs.size() >= 3;
}

std::optional<char> header_delimiter(std::string_view line) {
  for (char d : {'\t', ';', ',', ' '}) {
    if (line.find(d) == std::string_view::npos) continue;
    if (is_header(cells(line, d))) return d;
  }
  return std::nullopt;
}

}  // namespace

track::TrackSet parse_export_text(std::string_view text, const std::string& source,
                                  const std::string& default_name) {
  const std::vector<Line> ls = lines(text);
  std::size_t i = 0;
  auto skip = [&] {
    while (i < ls.size() && (trim(ls[i].text).empty() || trim(ls[i].text).front() == '#')) ++i;
  };
  skip();
  if (i >= ls.size()) throw InputError(source, "no data: the file holds only blank or # lines");
  std::optional<Line> name_row;
  std::optional<char> delim = header_delimiter(ls[i].text);
  if (!delim) {
    name_row = ls[i];
    ++i;
    if (i < ls.size()) delim = header_delimiter(ls[i].text);
    if (!delim) {
      throw InputError(at(source, name_row->number),
                       "expected a column-name row with t, x and y (Tracker's Export Data, or a "
                       "table with a header such as t,x,y)");
    }
  }
  const Line header = ls[i++];
  const std::vector<std::string_view> head = cells(header.text, *delim);
  std::vector<ColumnName> cols;
  for (auto c : head) cols.push_back(column_name(c));
  while (!cols.empty() && cols.back().base.empty()) cols.pop_back();  // trailing delimiter
  const std::size_t ncols = cols.size();

  // time column and its unit
  std::size_t tcol = ncols;
  for (std::size_t k = 0; k < ncols; ++k) {
    if (is_time_name(cols[k])) {
      tcol = k;
      break;
    }
  }
  const auto tunit = seconds_per_unit(cols[tcol].unit);
  if (!tunit) {
    throw InputError(at(source, header.number),
                     "unknown time unit '" + cols[tcol].unit.substr(0, 20) + "' (use s or ms)");
  }

  // track groups from the name row
  std::vector<std::pair<std::size_t, std::string>> names;
  if (name_row) {
    const auto nc = cells(name_row->text, *delim, ncols);
    for (std::size_t k = 0; k < nc.size(); ++k) {
      if (nc[k].empty()) continue;
      if (auto e = name_text_problem(nc[k]); !e.empty())
        throw InputError(at(source, name_row->number), "the track name in column " + std::to_string(k + 1) + " " + e);
      names.emplace_back(k, std::string(nc[k]));
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> ranges;  // [begin, end) of each group
  std::vector<Group> groups;
  if (names.size() <= 1) {
    ranges.emplace_back(0, ncols);
    groups.push_back({});
    groups.back().name = names.empty() ? default_name : names.front().second;
  } else {
    for (std::size_t g = 0; g < names.size(); ++g) {
      const std::size_t end = g + 1 < names.size() ? names[g + 1].first : ncols;
      ranges.emplace_back(names[g].first, std::max(end, names[g].first));
      groups.push_back({});
      groups.back().name = names[g].second;
    }
  }
  std::string length_unit;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::optional<std::size_t> x, y;
    for (std::size_t k = ranges[g].first; k < std::min(ranges[g].second, ncols); ++k) {
      const ColumnName& c = cols[k];
      if (c.base == "x" && !x) x = k;
      if (c.base == "y" && !y) y = k;
      if (c.base == "frame" && !groups[g].frame) groups[g].frame = k;
      if ((c.base == "x" || c.base == "y") && !c.unit.empty()) {
        if (!length_unit.empty() && length_unit != c.unit) {
          throw InputError(at(source, header.number),
                           "conflicting length units '" + length_unit + "' and '" + c.unit + "'");
        }
        length_unit = c.unit;
      }
    }
    if (!x || !y) {
      throw InputError(at(source, header.number), "track '" + groups[g].name + "' has no '" +
                                                      (x ? "y" : "x") + "' column");
    }
    groups[g].x = *x;
    groups[g].y = *y;
  }

  track::TrackSet set;
  set.source = source;
  set.format = "export";
  if (!length_unit.empty()) set.file_length_unit = length_unit;
  for (const Group& g : groups) set.tracks.push_back({g.name, {}});
  const bool decimal_comma = *delim != ',';
  long long row = -1;
  for (; i < ls.size(); ++i) {
    const Line& line = ls[i];
    const std::string_view tl = trim(line.text);
    if (tl.empty() || tl.front() == '#') continue;
    ++row;
    const std::string where = at(source, line.number);
    const auto cs = cells(line.text, *delim, ncols);
    for (std::size_t k = ncols; k < cs.size(); ++k) {
      if (!cs[k].empty()) {
        throw InputError(where, std::to_string(cs.size()) + " cells but the header has " +
                                    std::to_string(ncols) + " columns");
      }
    }
    auto cell = [&](std::size_t k) { return k < cs.size() ? cs[k] : std::string_view(); };
    const std::optional<double> t = parse_optional_double(cell(tcol), where, decimal_comma);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      Group& gr = groups[g];
      const auto x = parse_optional_double(cell(gr.x), where, decimal_comma);
      const auto y = parse_optional_double(cell(gr.y), where, decimal_comma);
      if (!x && !y) continue;  // no point of this track on this frame
      if (!x || !y) {
        throw InputError(where, "track '" + gr.name + "' has " + (x ? "x but no y" : "y but no x"));
      }
      if (!t) throw InputError(where, "a point of track '" + gr.name + "' has no time");
      check_track_value(*t, kMaxTrackTime, where, "t");
      check_track_value(*x, kMaxTrackCoordinate, where, "x of track '" + gr.name + "'");
      check_track_value(*y, kMaxTrackCoordinate, where, "y of track '" + gr.name + "'");
      long long frame = row;
      if (gr.frame) {
        const auto f = parse_optional_double(cell(*gr.frame), where, decimal_comma);
        if (!f) throw InputError(where, "track '" + gr.name + "' has a point without a frame number");
        if (*f != std::floor(*f) || *f < 0 || *f > static_cast<double>(kMaxFrameNumber)) {
          throw InputError(where, "frame must be a whole number from 0 to 1e8, got " + format_number(*f));
        }
        frame = static_cast<long long>(*f);
      }
      if (frame > kMaxFrameNumber) throw InputError(where, "too many rows (over 1e8)");
      const double ts = *t * *tunit;
      if (gr.any && frame <= gr.last_frame) {
        throw InputError(where, "track '" + gr.name + "': frame " + std::to_string(frame) +
                                    " does not follow frame " + std::to_string(gr.last_frame));
      }
      if (gr.any && !(ts > gr.last_t)) {
        throw InputError(where, "track '" + gr.name + "': time does not increase");
      }
      gr.any = true;
      gr.last_frame = frame;
      gr.last_t = ts;
      set.tracks[g].points.push_back({static_cast<int>(frame), ts, *x, *y});
    }
  }
  return set;
}

std::string write_export_text(const std::vector<track::Track>& tracks,
                              const ExportWriteOptions& o) {
  const char d = o.delimiter;
  if (o.decimal_comma && d == ',') {
    throw InputError("write_export_text", "a decimal comma needs a delimiter other than comma");
  }
  if (!o.tracker6 && tracks.size() > 1) {
    throw InputError("write_export_text", "the Tracker 5 layout holds one track");
  }
  const std::string u = o.length_unit.empty() ? "" : " (" + o.length_unit + ")";
  std::vector<std::string> per;
  if (o.frame_column) per.push_back("frame");
  per.push_back("x" + u);
  per.push_back("y" + u);
  if (o.extra_columns) {
    per.push_back("vx");
    per.push_back("vy");
  }
  // every frame from the first to the last, as Tracker writes them
  std::map<long long, double> times;
  for (const auto& tr : tracks) {
    for (const auto& p : tr.points) times.emplace(p.frame, p.t);
  }
  std::string out;
  if (o.name_row) {
    if (o.tracker6) {
      if (tracks.size() > 1) out += "#multi:\n";
      out += d;
      for (const auto& tr : tracks) {
        out += tr.name;
        out.append(per.size(), d);
      }
    } else {
      std::string name = tracks.empty() ? "" : tracks.front().name;
      std::replace(name.begin(), name.end(), ' ', '_');
      out += name;
    }
    out += '\n';
  }
  out += "t";
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    for (const auto& c : per) {
      out += d;
      out += c;
    }
  }
  if (o.tracker6) out += d;
  out += '\n';
  if (times.empty()) return out;
  std::vector<std::size_t> next(tracks.size(), 0);
  const long long first = times.begin()->first, last = times.rbegin()->first;
  for (long long f = first; f <= last; ++f) {
    double t;
    if (auto it = times.find(f); it != times.end()) {
      t = it->second;
    } else {  // a frame no track was marked on: Tracker still writes its time
      auto hi = times.upper_bound(f);
      auto lo = std::prev(hi);
      t = lo->second + (hi->second - lo->second) * static_cast<double>(f - lo->first) /
                           static_cast<double>(hi->first - lo->first);
    }
    out += exact(t, o.decimal_comma);
    for (std::size_t k = 0; k < tracks.size(); ++k) {
      const auto& pts = tracks[k].points;
      const bool has = next[k] < pts.size() && pts[next[k]].frame == f;
      for (const auto& c : per) {
        out += d;
        if (!has) continue;
        const auto& p = pts[next[k]];
        if (c == "frame") out += std::to_string(p.frame);
        if (c[0] == 'x') out += exact(p.x, o.decimal_comma);
        if (c[0] == 'y') out += exact(p.y, o.decimal_comma);
      }
      if (has) ++next[k];
    }
    out += '\n';
  }
  return out;
}

}  // namespace tribolab::io
