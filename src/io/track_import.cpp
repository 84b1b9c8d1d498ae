#include "io/track_import.hpp"

#include "numerics/physical_range.hpp"

#include "io/text.hpp"
#include "io/track_csv.hpp"
#include "io/tracker_export.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

namespace tribolab::io {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension(const std::string& source) {
  // the source may be "archive.trz:inner.trk"; the extension of the outer file decides
  return lower(std::filesystem::path(source).extension().string());
}

std::string stem(const std::string& source) {
  return std::filesystem::path(source).stem().string();
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

}  // namespace

std::string ImportOptions::validate() const {
  // Physical range: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  if (auto e = range_error(time_scale, ranges::time_scale, field("time_scale")); !e.empty())
    return e + " (real seconds per file second)";
  if (!length_unit.empty()) {
    try {
      metres_per_unit(length_unit, field("length_unit"));
    } catch (const InputError& e) {
      return marked_message(e);  // its field kept marked
    }
  }
  return "";
}

double metres_per_unit(const std::string& unit, const std::string& where) {
  const std::string u = lower(std::string(trim(unit)));
  if (u == "m" || u == "meter" || u == "metre" || u == "meters" || u == "metres") return 1;
  if (u == "cm") return 0.01;
  if (u == "mm") return 0.001;
  if (u == "km") return 1000;
  if (u == "um" || u == "\xc2\xb5m" || u == "\xce\xbcm") return 1e-6;
  if (u == "in" || u == "inch") return 0.0254;
  if (u == "ft" || u == "foot" || u == "feet") return 0.3048;
  throw InputError(where, "unknown length unit '" + std::string(unit.substr(0, 20)) +
                              "' (known: m, cm, mm, km, um, in, ft)");
}

void finish_import(track::TrackSet& set, const ImportOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  // Two tracks of one name: the option `track` could pick only the first, a series would mix them up.
  std::map<std::string, std::size_t> first_of;
  for (std::size_t i = 0; i < set.tracks.size(); ++i) {
    const auto [it, fresh] = first_of.emplace(set.tracks[i].name, i);
    if (!fresh)
      throw InputError(set.source, "two tracks are named '" + set.tracks[i].name + "' (tracks " +
                                       std::to_string(it->second + 1) + " and " + std::to_string(i + 1) +
                                       "): rename one");
  }
  // track selection (before the checks, so unwanted broken tracks do not matter)
  if (!options.tracks.empty()) {
    std::vector<track::Track> chosen;
    for (const std::string& name : options.tracks) chosen.push_back(set.find(name));
    set.tracks = std::move(chosen);
  }
  const std::string unit = options.length_unit.empty() ? set.file_length_unit : options.length_unit;
  const double k = metres_per_unit(unit, options.length_unit.empty() ? set.source + ": length unit"
                                                                      : field("length_unit"));
  set.file_length_unit = unit;
  set.time_scale = options.time_scale;
  bool any = false;
  for (track::Track& tr : set.tracks) {
    std::stable_sort(tr.points.begin(), tr.points.end(),
                     [](const auto& a, const auto& b) { return a.frame < b.frame; });
    for (track::TrackPoint& p : tr.points) {
      p.x *= k;
      p.y *= k;
      p.t *= options.time_scale;
    }
    track::validate_track(tr, set.source);
    any = any || !tr.points.empty();
  }
  if (!any) throw InputError(set.source, "no tracked points in the file");
}

track::TrackSet parse_tracks(std::string_view content, const std::string& source,
                             const ImportOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  if (starts_with(content, "\xef\xbb\xbf")) content.remove_prefix(3);  // UTF-8 byte order mark
  if (trim(content).empty()) throw InputError(source, "the file is empty");
  const std::string ext = extension(source);
  track::TrackSet set;
  const bool zip = starts_with(content, "PK\x03\x04") || starts_with(content, "PK\x05\x06");
  const std::string_view head = trim(content.substr(0, 64));
  if (ext == ".trz" || ext == ".zip" || (zip && ext != ".trk")) {
    set = read_trz(content, source, options.zip_entry);
  } else if (ext == ".trk" || starts_with(head, "<")) {
    set = parse_trk(content, source);
  } else if (looks_like_tidy_csv(content)) {
    set = parse_tidy_csv(content, source);
  } else {
    set = parse_export_text(content, source, stem(source));
  }
  finish_import(set, options);
  return set;
}

track::TrackSet read_tracks(const std::string& path, const ImportOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "is a directory, not a file");
  const std::string content = read_file(path);
  return parse_tracks(content, path, options);
}

}  // namespace tribolab::io
