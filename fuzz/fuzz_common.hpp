// Shared body of the fuzz targets: parse, and when the parse succeeds, differentiate every
// track both ways and look for impacts. Only InputError (a clear message about bad input) may
// escape the parsers; anything else - a crash, another exception, a sanitizer report, a hang,
// unbounded memory - is a bug libFuzzer reports.
#pragma once

#include "io/track_import.hpp"
#include "numerics/error.hpp"
#include "track/kinematics.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace tribolab::fuzz {

inline void exercise(const track::TrackSet& set) {
  for (const auto& tr : set.tracks) {
    if (tr.points.size() > 5000) continue;  // keep each input fast
    for (auto m : {track::DerivativeMethod::tracker, track::DerivativeMethod::savgol}) {
      track::KinematicsOptions o;
      o.method = m;
      o.window = 5;
      try {
        (void)track::differentiate(tr, o);
      } catch (const InputError&) {
      }
    }
  }
}

inline int run(const uint8_t* data, size_t size, const std::string& source) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    exercise(io::parse_tracks(bytes, source));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace tribolab::fuzz
