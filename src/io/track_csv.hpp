// Tidy CSV of tracked points, one row per marked point:
//   track,frame,t,x,y
//   ball,2,0.132,0,0
// (what `tribolab track import --out` writes; columns in any order, comma, semicolon or tab
// delimited, decimal comma accepted with ; or tab, units in the header as "x (cm)"), and the
// kinematics table t,x,y,vx,vy,ax,ay[,sigma_vx,sigma_vy,sigma_ax,sigma_ay].
#pragma once

#include "track/kinematics.hpp"
#include "track/track.hpp"

#include <ostream>
#include <string>
#include <string_view>

namespace tribolab::io {

/// True when the first non-blank, non-# line's first cell is "track".
bool looks_like_tidy_csv(std::string_view text);

/// Parses a tidy CSV (lengths in the file's unit). Errors name file:line.
track::TrackSet parse_tidy_csv(std::string_view text, const std::string& source);

/// Writes track,frame,t,x,y with exact (shortest round-trip) numbers, in metres and seconds.
void write_tidy_csv(std::ostream& out, const track::TrackSet& set);

/// Writes t,x,y,vx,vy,ax,ay (empty cells where undefined); with `sigmas`, also the trailing
/// columns sigma_vx,sigma_vy,sigma_ax,sigma_ay.
void write_kinematics_csv(std::ostream& out, const track::Kinematics& k, bool sigmas);

}  // namespace tribolab::io
