// Tracker's "Export Data" text, and plain tables with a header (t,x,y; frame,t,x,y; ...).
//
// Layout read (Tracker 5 and 6; docs/theory.md#tracker-export):
//   [#multi:]                               only when several tracks are exported together
//   [<d>]name A[<d>...]name B...            optional track-name row: each name sits above the
//                                           first column of its track's group
//   t<d>x<d>y<d>vx...[<d>x<d>y...]          column names; the time column first
//   0.0<d>1.2E-1<d>...                      one row per frame; empty cells where a track has
//                                           no point (e.g. the frames skipped by a step size)
// <d> is tab, semicolon, comma or space (detected from the column-name row). With a delimiter
// other than comma, a decimal comma is accepted ("1,25E-1"). A unit in a column name
// ("x (cm)", "x [mm]", "t (ms)") is honoured. Columns "x" and "y" are required for each track,
// "frame" is used when present (else the frame is the row index); other columns are ignored.
// Lines starting with '#' before the header are skipped. Errors name file:line.
#pragma once

#include "track/track.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace tribolab::io {

/// Parses export text; `default_name` names the single track when the file has no name row.
/// Lengths are in the file's unit (TrackSet::file_length_unit), times in seconds.
track::TrackSet parse_export_text(std::string_view text, const std::string& source,
                                  const std::string& default_name);

/// How write_export_text lays the text out (the variants Tracker and users produce).
struct ExportWriteOptions {
  char delimiter = '\t';       ///< '\t', ',', ';' or ' '
  bool decimal_comma = false;  ///< write 1,5 instead of 1.5 (not with ',' as delimiter)
  bool tracker6 = true;        ///< Tracker 6 layout (leading delimiter, "#multi:", trailing
                               ///< delimiters); false: Tracker 5 (a bare name line)
  bool name_row = true;        ///< write the track-name row (false: a plain table)
  bool frame_column = false;   ///< add a "frame" column to each track's group
  bool extra_columns = false;  ///< add Tracker's vx, vy columns (empty) to test they are skipped
  std::string length_unit;     ///< "" = none; else written in the x, y headers: "x (cm)"
};

/// Export text holding `tracks` (t, x, y in seconds and the file's length unit), one row per
/// frame where any track has a point, exact to the last bit (shortest round-trip numbers).
std::string write_export_text(const std::vector<track::Track>& tracks,
                              const ExportWriteOptions& options = {});

}  // namespace tribolab::io
