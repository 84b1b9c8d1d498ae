// Reading tracked video data into track::TrackSet (src/track/track.hpp), whatever the file:
//   * Tracker project files: .trk (XML) and .trz (zip holding a .trk)   -> tracker_trk.hpp
//   * Tracker "Export Data" text and plain tables with a t,x,y header    -> tracker_export.hpp
//   * tidy CSV with a track,frame,t,x,y header (what `track import` writes) -> track_csv.hpp
// The format is chosen by extension (.trk, .trz, .zip) and otherwise by content. Every
// importer returns lengths in the file's unit; read_tracks then converts to metres, applies
// the slow-motion time scale, selects tracks and checks the invariants of track.hpp.
#pragma once

#include "track/track.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace tribolab::io {

struct ImportOptions {
  /// Multiplies every time: real seconds per file second. Slow motion recorded at 240 fps and
  /// played at 30 fps: 30/240 = 0.125. Default 1.
  double time_scale = 1;
  /// Unit of the file's lengths: "" = what the file says (Tracker's length_unit, a unit in a
  /// column header such as "x (cm)"), metres if it says nothing; else one of m, cm, mm, km,
  /// in, ft, which overrides the file.
  std::string length_unit;
  /// Keep only these tracks, in this order (empty = all). Unknown names are an error that
  /// lists the available tracks.
  std::vector<std::string> tracks;
  /// .trz only: name of the .trk inside the zip to read ("" = the first .trk).
  std::string zip_entry;
  /// Empty when valid, else a message naming the option.
  std::string validate() const;
};

/// Metres per `unit` (m, cm, mm, km, um, in, ft; case-insensitive); throws InputError(where)
/// for anything else.
double metres_per_unit(const std::string& unit, const std::string& where);

/// Reads `path`, detecting the format. Throws InputError naming the file (and line or XML
/// element) for anything wrong.
track::TrackSet read_tracks(const std::string& path, const ImportOptions& options = {});

/// Same from bytes already in memory; `source` names them in messages ("file.trk") and its
/// extension guides detection.
track::TrackSet parse_tracks(std::string_view content, const std::string& source,
                             const ImportOptions& options = {});

/// Applies ImportOptions to a TrackSet in file units: unit conversion, time scale, track
/// selection, sorting by frame and validation. Used by parse_tracks.
void finish_import(track::TrackSet& set, const ImportOptions& options);

}  // namespace tribolab::io
