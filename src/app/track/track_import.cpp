#include "app/track/track_import.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"

#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>

namespace tribolab::app {

namespace {

nlohmann::json summary(const track::Track& t) {
  nlohmann::json j;
  j["points"] = t.points.size();
  if (t.points.empty()) return j;
  double x0 = t.points[0].x, x1 = x0, y0 = t.points[0].y, y1 = y0;
  for (const auto& p : t.points) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  j["frame_first"] = t.points.front().frame;
  j["frame_last"] = t.points.back().frame;
  j["t_min"] = t.points.front().t;
  j["t_max"] = t.points.back().t;
  j["x_min"] = x0;
  j["x_max"] = x1;
  j["y_min"] = y0;
  j["y_max"] = y1;
  return j;
}

}  // namespace

io::ImportOptions import_options(const TrackInputOptions& input, std::vector<std::string> tracks) {
  io::ImportOptions o;
  o.time_scale = input.time_scale;
  o.length_unit = input.length_unit;
  o.zip_entry = input.entry;
  o.tracks = std::move(tracks);
  return o;
}

const track::Track& choose_track(const track::TrackSet& set, const std::string& wanted) {
  if (!wanted.empty()) return set.find(wanted);
  std::vector<const track::Track*> with_points;
  for (const auto& t : set.tracks) {
    if (!t.points.empty()) with_points.push_back(&t);
  }
  if (with_points.size() == 1) return *with_points.front();
  std::string names;
  for (const auto* t : with_points) names += (names.empty() ? "'" : ", '") + t->name + "'";
  throw InputError(set.source, "the file holds " + std::to_string(with_points.size()) +
                                   " tracks (" + names + "); choose one with " + field("track"));
}

TrackImportResult track_import(const TrackImportOptions& options) {
  check_output_paths({options.input.file}, {{"out", options.out}});  // before any work (app/common/output_paths.hpp)
  const track::TrackSet set = io::read_tracks(options.input.file, import_options(options.input, options.track));
  TrackImportResult r;
  nlohmann::json& j = r.json;
  j["source"] = set.source;
  j["format"] = set.format;
  j["length_unit_in_file"] = set.file_length_unit;
  j["time_scale"] = set.time_scale;
  j["track_names"] = set.names();
  nlohmann::json tracks = nlohmann::json::object();
  for (const auto& t : set.tracks) tracks[t.name] = summary(t);
  j["tracks"] = tracks;
  j["warnings"] = set.warnings;
  j["out"] = options.out.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.out);
  if (!options.out.empty()) {
    io::AtomicFile f(options.out);
    io::write_tidy_csv(f.stream(), set);
    f.commit();
  }
  r.tracks = set.tracks;
  return r;
}


const ResultKeys& track_import_result_keys() {
  static const ResultKeys k = {
      {"source", "", ""}, {"format", "", "export, trk, csv"}, {"length_unit_in_file", "", "the unit the file names"},
      {"time_scale", "", "real seconds per file second"}, {"track_names", "", ""},
      {"tracks.*.frame_first", "", ""}, {"tracks.*.frame_last", "", ""}, {"tracks.*.points", "", ""},
      {"tracks.*.t_min", "s", ""}, {"tracks.*.t_max", "s", ""}, {"tracks.*.x_min", "m", ""},
      {"tracks.*.x_max", "m", ""}, {"tracks.*.y_min", "m", ""}, {"tracks.*.y_max", "m", ""},
      {"warnings", "", ""}, {"out", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
