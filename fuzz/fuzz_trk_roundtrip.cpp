// libFuzzer target: the .trk writer and reader agree. Bytes that parse as a Tracker project
// are written back by write_trk (same clip, coordinate system, unit, video and marks) and
// read again: the second read must succeed and give the same video, clip, tracks, frames and
// times exactly, and the same pixel marks to rounding. A mismatch aborts, which libFuzzer
// reports with the input that caused it.
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

using namespace tribolab;

[[noreturn]] void mismatch(const std::string& what) {
  std::fprintf(stderr, "trk round trip: %s\n", what.c_str());
  std::abort();
}

/// The pixel -> world -> pixel round trip loses a few ulps of the largest term, amplified by
/// the ratio of the two scales when the axes are rotated.
double tolerance(const io::TrkCoordFrame& c, double px, double py) {
  const double ratio = std::max(c.xscale / c.yscale, c.yscale / c.xscale);
  return 1e-12 * (1 + std::abs(px) + std::abs(py) + std::abs(c.origin_x) + std::abs(c.origin_y)) *
         std::max(1.0, ratio);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  io::TrkProject p;
  try {
    p = io::parse_trk_project(bytes, "fuzz.trk");
  } catch (const InputError&) {
    return 0;
  }
  io::TrkWriteSpec spec;
  spec.coords = p.coords;
  if (spec.coords.front().frame != 0) {  // the key in force before the first key is the first
    io::TrkCoordFrame first = spec.coords.front();
    first.frame = 0;
    spec.coords.insert(spec.coords.begin(), first);
  }
  spec.start_frame = p.clip.start_frame;
  spec.step_size = p.clip.step_size;
  spec.step_count = p.clip.step_count;
  spec.start_time_ms = p.clip.start_time_ms;
  spec.frame_duration_ms = p.clip.frame_duration_ms;
  spec.length_unit = p.length_unit;
  spec.video_path = p.video_path;
  spec.video_frame_count = p.video_frame_count;
  std::vector<track::Track> world = p.marks_px;
  for (auto& t : world) {
    for (auto& pt : t.points) {
      const auto [x, y] = io::image_to_world(io::coord_at(p.coords, pt.frame), pt.x, pt.y);
      pt.x = x;
      pt.y = y;
    }
  }
  std::string xml;
  try {
    xml = io::write_trk(world, spec);
  } catch (const InputError&) {
    return 0;  // e.g. a position that maps to no finite pixel: refused, not written wrong
  }
  io::TrkProject q;
  try {
    q = io::parse_trk_project(xml, "again.trk");
  } catch (const InputError& e) {
    mismatch(std::string("the written project does not read back: ") + e.what());
  }
  if (q.video_path != p.video_path) mismatch("video path");
  if (q.video_frame_count != p.video_frame_count) mismatch("video frame count");
  if (q.length_unit != p.length_unit) mismatch("length unit");
  if (q.clip.start_frame != p.clip.start_frame || q.clip.step_size != p.clip.step_size ||
      q.clip.start_time_ms != p.clip.start_time_ms ||
      q.clip.frame_duration_ms != p.clip.frame_duration_ms ||
      (p.clip.step_count > 0 && q.clip.step_count != p.clip.step_count)) {
    mismatch("clip");
  }
  if (q.marks_px.size() != p.marks_px.size()) mismatch("number of tracks");
  for (std::size_t i = 0; i < p.marks_px.size(); ++i) {
    const auto& a = p.marks_px[i];
    const auto& b = q.marks_px[i];
    if (a.name != b.name) mismatch("track name '" + a.name + "'");
    if (a.points.size() != b.points.size()) mismatch("points of track '" + a.name + "'");
    for (std::size_t j = 0; j < a.points.size(); ++j) {
      const auto& u = a.points[j];
      const auto& v = b.points[j];
      const io::TrkCoordFrame& c = io::coord_at(p.coords, u.frame);
      const io::TrkCoordFrame& d = io::coord_at(q.coords, u.frame);
      if (c.origin_x != d.origin_x || c.origin_y != d.origin_y || c.angle_deg != d.angle_deg ||
          c.xscale != d.xscale || c.yscale != d.yscale) {
        mismatch("coordinate system at frame " + std::to_string(u.frame));
      }
      if (u.frame != v.frame || u.t != v.t) mismatch("frame or time of track '" + a.name + "'");
      const double tol = tolerance(c, u.x, u.y);
      if (!(std::abs(u.x - v.x) <= tol && std::abs(u.y - v.y) <= tol)) {
        mismatch("pixel position of track '" + a.name + "' frame " + std::to_string(u.frame));
      }
    }
  }
  return 0;
}
