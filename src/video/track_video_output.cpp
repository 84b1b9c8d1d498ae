// What `track video` writes: the CSV table and the Tracker project (track_video.hpp).
#include "video/track_video.hpp"

#include "io/text.hpp"
#include "io/track_text.hpp"

#include <filesystem>
#include <ostream>

namespace tribolab::video {

void write_csv(std::ostream& out, const TrackVideoResult& result) {
  using io::tracktext::exact;
  out << "track,frame,t,x,y,x_px,y_px,score\n";
  for (const TrackedSeries& s : result.series) {
    const std::string name = io::csv_quote(s.name);
    for (const TrackedRow& r : s.rows) {
      out << name << ',' << r.frame << ',' << exact(r.t) << ',';
      if (r.lost) {
        out << ",,,,0\n";
      } else {
        out << exact(r.x) << ',' << exact(r.y) << ',' << exact(r.x_px) << ',' << exact(r.y_px)
            << ',' << exact(r.score) << '\n';
      }
    }
  }
}

io::TrkWriteSpec trk_spec(const TrackVideoResult& result, const std::string& trk_path,
                          std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  const VideoInput& in = result.input;
  io::TrkWriteSpec spec;
  // world metres = image_to_world(key with scales / metres_per_unit): the project is written
  // in metres whatever unit the input project used (px for an uncalibrated video)
  // (and in Tracker's image positions, half a pixel from OpenCV's: kTrackerPixelOffset)
  spec.coords.clear();
  for (const auto& c : in.calibration.coords) spec.coords.push_back(to_tracker_pixels(c));
  for (auto& c : spec.coords) {
    c.xscale /= in.calibration.metres_per_unit;
    c.yscale /= in.calibration.metres_per_unit;
  }
  if (spec.coords.empty() || spec.coords.front().frame != 0) {
    io::TrkCoordFrame first = spec.coords.empty() ? io::TrkCoordFrame{} : spec.coords.front();
    first.frame = 0;
    spec.coords.insert(spec.coords.begin(), first);
  }
  spec.length_unit = in.calibration.calibrated ? "m" : "px";
  spec.start_frame = in.clip.start_frame;
  spec.step_size = in.clip.step_size;
  spec.step_count = in.clip.step_count > 0 ? in.clip.step_count : result.frames;
  // Tracker's frame duration holds any slow-motion factor: real seconds per frame
  spec.start_time_ms = in.time.start_time_s * in.time.time_scale * 1000;
  spec.frame_duration_ms = in.time.real_frame_s() * 1000;
  spec.video_frame_count = in.info.frame_count;
  if (in.video_file.empty()) {
    warnings.push_back(trk_path + ": the video lives inside " + in.input +
                       ", so the written project names no video (open it in Tracker and import the video)");
  } else {
    std::error_code ec;
    const fs::path dir = fs::absolute(fs::path(trk_path), ec).parent_path();
    const fs::path video = fs::absolute(fs::path(in.video_file), ec);
    fs::path rel = video.lexically_relative(dir);
    spec.video_path = (rel.empty() ? video : rel).generic_string();
  }
  return spec;
}

}  // namespace tribolab::video
