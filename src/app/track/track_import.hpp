// `tribolab track import` (docs/cli.md#track), and the input group shared by every command
// that reads tracked points (import, kinematics, rigid-body): the file, its time scale, its
// length unit and the .trz entry. Front ends (CLI, Python) fill the options and print `json`.
#pragma once

#include "app/common/option_fields.hpp"
#include "io/track_import.hpp"
#include "track/track.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tribolab::app {

/// Where the tracked points come from (FILE, --time-scale, --length-unit, --entry).
struct TrackInputOptions {
  std::string file;          ///< Tracker .trk/.trz, Tracker Export Data text, or a CSV table
  double time_scale = 1;     ///< real seconds per file second (240 fps played at 30 fps: 0.125)
  std::string length_unit;   ///< unit of the file's lengths (m, cm, mm, km, um, in, ft); empty: the file's, else m
  std::string entry;         ///< .trz only: the .trk inside to read; empty: the first
};

/// The declaration of the input group (app/common/option_fields.hpp): FILE, --time-scale,
/// --length-unit, --entry.
inline const Fields<TrackInputOptions>& track_input_fields() {
  using O = TrackInputOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("file", &O::file, "", "Tracker .trk/.trz, Tracker Export Data text, or CSV").as(FieldRole::input_files).needed();
    d.add("time_scale", &O::time_scale, "", "real seconds per file second (240 fps played at 30 fps: 0.125)")
        .in(ranges::time_scale);
    d.add("length_unit", &O::length_unit, "",
          "unit of the file's lengths, overriding the file's (m, cm, mm, km, um, in, ft; when not given: the file's "
          "unit, else m)");
    d.add("entry", &O::entry, "", "for a .trz: the .trk inside to read (when not given: the first)");
    return d;
  }();
  return f;
}

/// The library's import options from the input group, keeping only `tracks` (empty = all).
io::ImportOptions import_options(const TrackInputOptions& input, std::vector<std::string> tracks = {});

/// The one track to analyse: `wanted` when given, else the only track with points.
/// Throws InputError naming the file and "--track" when the choice is ambiguous.
const track::Track& choose_track(const track::TrackSet& set, const std::string& wanted);

struct TrackImportOptions {
  TrackInputOptions input;
  std::vector<std::string> track;  ///< keep only these tracks, in this order; empty: all
  std::string out;                 ///< tidy CSV track,frame,t,x,y (s, m); empty: not written
};

/// The declaration of every option of `track import` (app/common/option_fields.hpp): the
/// command line and Python (`tribolab.track.load`) bind from it.
inline const Fields<TrackImportOptions>& track_import_fields() {
  using O = TrackImportOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::input, track_input_fields());
    d.add("track", &O::track, "", "keep only this track (repeatable; when not given: all)");
    d.add("out", &O::out, "", "write the tidy CSV here (columns track,frame,t,x,y)").as(FieldRole::output_path);
    return d;
  }();
  return f;
}

struct TrackImportResult {
  nlohmann::json json;              ///< what `track import --json` prints
  std::vector<track::Track> tracks; ///< per track its points: frame, t (s), x, y (m)
};

/// Reads the file (any format of io/track_import.hpp), writes the tidy CSV when asked and
/// summarises every track. Throws InputError naming the file (and line) or the option.
TrackImportResult track_import(const TrackImportOptions& options);

}  // namespace tribolab::app
