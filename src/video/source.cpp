// Opening a video or a Tracker project for tracking (source.hpp).
#include "video/source.hpp"

#include "io/temp_files.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "video/codec.hpp"

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>  // the cv::CAP_PROP_* names; decoding is codec.hpp's

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <regex>
#include <unistd.h>

namespace tribolab::video {

namespace fs = std::filesystem;

bool Clip::contains(int frame) const {
  const long long rel = static_cast<long long>(frame) - start_frame;
  return rel >= 0 && rel % step_size == 0 && (step_count <= 0 || rel / step_size < step_count);
}

double TimeBase::t(int frame) const {
  return (start_time_s + static_cast<double>(frame - start_frame) * frame_duration_s) * time_scale;
}

io::TrkCoordFrame from_tracker_pixels(io::TrkCoordFrame c) {
  c.origin_x -= kTrackerPixelOffset;
  c.origin_y -= kTrackerPixelOffset;
  return c;
}

io::TrkCoordFrame to_tracker_pixels(io::TrkCoordFrame c) {
  c.origin_x += kTrackerPixelOffset;
  c.origin_y += kTrackerPixelOffset;
  return c;
}

const io::TrkCoordFrame& Calibration::at(int frame) const { return io::coord_at(coords, frame); }

std::pair<double, double> Calibration::to_world(int frame, double px, double py) const {
  // the same arithmetic as io::parse_trk followed by io::finish_import's unit conversion,
  // so a project's marks land on exactly the numbers `track import` gives
  auto [x, y] = io::image_to_world(at(frame), px, py);
  x *= metres_per_unit;
  y *= metres_per_unit;
  return {x, y};
}

std::pair<double, double> Calibration::to_image(int frame, double x, double y) const {
  return io::world_to_image(at(frame), x / metres_per_unit, y / metres_per_unit);
}

namespace {

/// A scale of metres per pixel: from a microscope to a stadium seen by one pixel.
constexpr PhysicalRange kScale{0, 1e3, "m/px", true};
/// Largest image coordinate accepted for `origin` and `calibrate` points, px.
constexpr double kMaxPixel = 1e6;

std::string point_error(const cv::Point2d& p, const std::string& name) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kMaxPixel ||
      std::abs(p.y) > kMaxPixel) {
    return name + ": image coordinates must be finite pixels within 1e6";
  }
  return "";
}

}  // namespace

std::string SourceOptions::validate() const {
  if (fps != 0) {
    if (auto e = range_error(fps, ranges::frame_rate, field("fps")); !e.empty()) return e;
  }
  if (auto e = range_error(time_scale, ranges::time_scale, field("time_scale")); !e.empty())
    return e + " (real seconds per video second)";
  if (scale_m_per_px != 0) {
    if (auto e = range_error(scale_m_per_px, kScale, field("scale")); !e.empty()) return e;
  }
  if (calibrate_points) {
    if (scale_m_per_px != 0) return field("scale") + " and " + field("calibrate") + ": give one of them, not both";
    for (const auto& p : {calibrate_points->first, calibrate_points->second}) {
      if (auto e = point_error(p, field("calibrate")); !e.empty()) return e;
    }
    if (cv::norm(calibrate_points->second - calibrate_points->first) < 1) {
      return field("calibrate") + ": the two ends of the stick must be at least 1 px apart";
    }
    if (auto e = range_error(calibrate_length_m, ranges::distance, field("calibrate")); !e.empty())
      return e + " (the stick's length)";
  } else if (calibrate_length_m != 0) {
    return field("calibrate") + ": the stick's length needs its two ends";
  }
  if (origin_px) {
    if (auto e = point_error(*origin_px, field("origin")); !e.empty()) return e;
  }
  if (auto e = range_error(axes_deg, ranges::angle_deg, field("axes_deg")); !e.empty()) return e;
  return "";
}

namespace {

/// FFmpeg and OpenCV print their own diagnostics on stderr; tribolab reports every failure
/// as one InputError instead. A user who sets OPENCV_FFMPEG_LOGLEVEL or OPENCV_FFMPEG_DEBUG
/// keeps FFmpeg's messages.
void quiet_decoder_logs() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (std::getenv("OPENCV_FFMPEG_LOGLEVEL") == nullptr &&
        std::getenv("OPENCV_FFMPEG_DEBUG") == nullptr) {
      ::setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
    }
    if (std::getenv("OPENCV_LOG_LEVEL") == nullptr) {
      cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    }
  });
}

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string fourcc_text(double code) {
  const auto v = static_cast<unsigned>(std::max(0.0, code));
  std::string s;
  for (int k = 0; k < 4; ++k) {
    const char c = static_cast<char>((v >> (8 * k)) & 0xff);
    s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return v == 0 ? std::string() : s;
}

void require_regular_file(const std::string& path, const std::string& where) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(where, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(where, "is a directory, not a video");
}

/// Opens `path` with FFmpeg and decodes its first frame: a file that opens but yields no
/// frame (truncated, wrong codec) is refused here, before any tracking.
VideoInfo probe_video(const std::string& path, const std::string& where) {
  quiet_decoder_logs();
  // (an image sequence is an FFmpeg pattern such as frame%04d.jpg, not one file)
  if (path.find('%') == std::string::npos) require_regular_file(path, where);
  std::unique_ptr<VideoFileReader> cap;
  try {
    cap = open_video_file(path);
  } catch (const cv::Exception&) {
    // OpenCV throws for some unreadable inputs; reported below as not decodable
  }
  if (!cap) {
    throw InputError(where, "cannot be decoded as a video (FFmpeg does not recognise the "
                            "container or its codec; is it a video file?)");
  }
  cv::Mat first;
  bool ok = false;
  try {
    ok = cap->read(first);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok || first.empty()) {
    throw InputError(where, "no frame could be decoded (truncated or corrupt video?)");
  }
  VideoInfo info;
  info.path = path;
  info.width = first.cols;
  info.height = first.rows;
  const double n = cap->get(cv::CAP_PROP_FRAME_COUNT);
  info.frame_count = std::isfinite(n) && n > 0 && n < 1e8 ? static_cast<int>(std::lround(n)) : 0;
  const double fps = cap->get(cv::CAP_PROP_FPS);
  info.fps = std::isfinite(fps) && fps > 0 && fps <= 1e5 ? fps : 0;
  info.codec = fourcc_text(cap->get(cv::CAP_PROP_FOURCC));
  return info;
}

/// The calibration of a plain video from the options (pixels, y up, when no scale is given).
Calibration plain_calibration(const SourceOptions& o, const VideoInfo& info,
                              std::vector<std::string>& warnings) {
  double px_per_m = 0;
  if (o.scale_m_per_px > 0) {
    px_per_m = 1 / o.scale_m_per_px;
  } else if (o.calibrate_points) {
    px_per_m = cv::norm(o.calibrate_points->second - o.calibrate_points->first) / o.calibrate_length_m;
  }
  io::TrkCoordFrame c;
  c.frame = 0;
  // default origin: the centre of the bottom-left pixel, so x and y >= 0 across the image
  const cv::Point2d origin = o.origin_px.value_or(cv::Point2d(0, info.height - 1));
  c.origin_x = origin.x;
  c.origin_y = origin.y;
  c.angle_deg = o.axes_deg;
  c.xscale = c.yscale = px_per_m > 0 ? px_per_m : 1;
  Calibration cal;
  cal.coords = {c};
  cal.metres_per_unit = 1;
  cal.calibrated = px_per_m > 0;
  if (!cal.calibrated) {
    warnings.push_back("no scale (" + field("scale") + " or " + field("calibrate") + "): positions x, y are in pixels (y up)");
  }
  return cal;
}

bool calibration_given(const SourceOptions& o) {
  return o.scale_m_per_px > 0 || o.calibrate_points || o.origin_px || o.axes_deg != 0;
}

/// A temporary file removed when the last VideoInput or FrameReader using it is gone.
struct TempFile {
  std::string path;
  std::unique_ptr<io::TempRegistration> on_signal;  // a signal removes it as well
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

std::shared_ptr<TempFile> make_temp_file(const std::string& extension) {
  std::string name = (fs::temp_directory_path() / "tribolab_video_XXXXXX").string() + extension;
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  auto t = std::make_shared<TempFile>();
  const int fd = ::mkstemps(buf.data(), static_cast<int>(extension.size()));
  if (fd < 0) throw InputError(name, "cannot create a temporary file for the video");
  t->on_signal = std::make_unique<io::TempRegistration>(buf.data());
  t->path = buf.data();
  ::close(fd);
  return t;
}

/// A temporary folder removed, with what it holds, when the last user is gone.
struct TempDir {
  std::string path;
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/// Tracker's ImageVideo: numbered images (NAME00.jpg, NAME01.jpg, ...) are the frames. When
/// `entry` is one, the archive's images of the same folder, name and number width are
/// extracted in number order as frame%0Nd.EXT into a temporary folder, and the FFmpeg
/// pattern naming them is returned with the folder's owner; otherwise "".
std::pair<std::string, std::shared_ptr<TempDir>> extract_image_sequence(const std::string& trz, const std::string& entry,
                                                                       const std::vector<std::string>& entries) {
  static const std::regex numbered(R"(^(.*?)(\d+)\.(jpe?g|png|bmp|gif)$)", std::regex::icase);
  std::smatch m;
  if (!std::regex_match(entry, m, numbered)) return {"", nullptr};
  const std::string prefix = m[1], ext = m[3];
  const std::size_t width = static_cast<std::size_t>(m[2].length());
  std::vector<std::pair<long, std::string>> frames;
  for (const auto& e : entries) {
    std::smatch k;
    if (std::regex_match(e, k, numbered) && k[1] == prefix && static_cast<std::size_t>(k[2].length()) == width && k[3] == ext) {
      frames.emplace_back(std::stol(k[2]), e);
    }
  }
  std::sort(frames.begin(), frames.end());
  std::string dir = (fs::temp_directory_path() / "tribolab_frames_XXXXXX").string();
  std::vector<char> buf(dir.begin(), dir.end());
  buf.push_back('\0');
  if (::mkdtemp(buf.data()) == nullptr) throw InputError(trz, "cannot create a temporary folder for the image sequence");
  auto owner = std::make_shared<TempDir>();
  owner->path = buf.data();
  const int digits = std::clamp(static_cast<int>(width), 4, 9);  // names stay short
  char name[64];
  for (std::size_t i = 0; i < frames.size(); ++i) {
    std::snprintf(name, sizeof name, "frame%0*d.", digits, static_cast<int>(i));
    io::extract_zip_entry(trz, frames[i].second, owner->path + "/" + name + ext);
  }
  return {owner->path + "/frame%0" + std::to_string(digits) + "d." + ext, owner};
}

std::string normalise(std::string p) {
  std::replace(p.begin(), p.end(), '\\', '/');
  while (p.rfind("./", 0) == 0) p.erase(0, 2);
  return p;
}

/// The video of a project on disk: its path relative to the project's folder (or absolute),
/// else a file of the same name beside the project.
std::string find_video_beside(const std::string& project_path, const std::string& video) {
  const fs::path dir = fs::path(project_path).parent_path();
  const fs::path named(normalise(video));
  std::vector<fs::path> candidates;
  candidates.push_back(named.is_absolute() ? named : dir / named);
  candidates.push_back(dir / named.filename());
  std::error_code ec;
  for (const auto& c : candidates) {
    if (fs::is_regular_file(c, ec)) return c.string();
  }
  throw InputError(project_path, "the project's video '" + video + "' was not found (looked for " +
                                     candidates.front().string() + ")");
}

/// Clip, time base and calibration of a Tracker project, with any option overriding them.
void apply_project(VideoInput& in, const io::TrkProject& p, const SourceOptions& o) {
  in.project_video = p.video_path;
  in.clip.start_frame = p.clip.start_frame;
  in.clip.step_size = p.clip.step_size;
  in.clip.step_count = p.clip.step_count;
  in.time.start_frame = p.clip.start_frame;
  in.time.start_time_s = p.clip.start_time_ms / 1000;
  in.time.frame_duration_s = p.clip.frame_duration_ms / 1000;
  in.time.time_scale = o.time_scale;
  if (o.fps > 0) {
    in.warnings.push_back(field("fps") + " " + io::format_number(o.fps) + " overrides the project's frame duration of " +
                          io::format_number(p.clip.frame_duration_ms) + " ms");
    in.time.frame_duration_s = 1 / o.fps;
  }
  if (calibration_given(o)) {
    in.warnings.push_back("calibration options override the project's coordinate system");
    in.calibration = plain_calibration(o, in.info, in.warnings);
  } else {
    // Marks and origins both move by the same half pixel, so track video's world positions of
    // the marks are track import's (the differences px - origin are exact, bit for bit).
    in.calibration.coords.clear();
    for (const auto& c : p.coords) in.calibration.coords.push_back(from_tracker_pixels(c));
    in.calibration.metres_per_unit = io::metres_per_unit(p.length_unit, p.source + ": length unit");
    in.calibration.calibrated = true;
  }
  for (const auto& w : p.warnings) in.warnings.push_back(w);
  in.marks_px = p.marks_px;
  for (auto& tr : in.marks_px) {
    for (auto& pt : tr.points) {
      pt.t = in.time.t(pt.frame);
      pt.x -= kTrackerPixelOffset;
      pt.y -= kTrackerPixelOffset;
    }
  }
}

VideoInput open_plain(const std::string& path, const SourceOptions& o) {
  VideoInput in;
  in.input = path;
  in.info = probe_video(path, path);
  in.video_file = path;
  in.time.frame_duration_s = o.fps > 0 ? 1 / o.fps : (in.info.fps > 0 ? 1 / in.info.fps : 0);
  if (!(in.time.frame_duration_s > 0)) {
    throw InputError(path, "the video states no frame rate: give it with " + field("fps"));
  }
  in.time.time_scale = o.time_scale;
  in.frame_times_from_timestamps = !(o.fps > 0);
  in.calibration = plain_calibration(o, in.info, in.warnings);
  return in;
}

VideoInput open_trk(const std::string& path, const SourceOptions& o) {
  require_regular_file(path, path);
  const io::TrkProject p = io::parse_trk_project(io::read_file(path), path);
  if (p.video_path.empty()) {
    throw InputError(path, "the project names no video (videoclip/video/path): there is nothing to track");
  }
  VideoInput in;
  in.input = path;
  const std::string video = find_video_beside(path, p.video_path);
  in.info = probe_video(video, video);
  in.video_file = video;
  apply_project(in, p, o);
  return in;
}

VideoInput open_trz(const std::string& path, const SourceOptions& o) {
  require_regular_file(path, path);
  const io::TrzContents z = io::read_trz_file(path, o.zip_entry);
  const io::TrkProject& p = z.project;
  if (p.video_path.empty()) {
    throw InputError(z.project.source, "the project names no video (videoclip/video/path): "
                                       "there is nothing to track");
  }
  // the video's path is relative to the .trk's folder inside the archive
  const std::string trk_dir = fs::path(z.trk_entry).parent_path().string();
  const std::string wanted = normalise(trk_dir.empty() ? p.video_path : trk_dir + "/" + p.video_path);
  const std::string base = fs::path(normalise(p.video_path)).filename().string();
  std::string entry;
  for (const auto& e : z.entries) {
    if (normalise(e) == wanted) entry = e;
  }
  for (const auto& e : z.entries) {
    if (entry.empty() && fs::path(normalise(e)).filename().string() == base) entry = e;
  }
  VideoInput in;
  in.input = path;
  if (entry.empty()) {
    // Tracker may save a .trz whose video stays beside it
    std::string beside;
    try {
      beside = find_video_beside(path, p.video_path);
    } catch (const InputError&) {
      throw InputError(path, "the archive holds no video: the project names '" + p.video_path +
                                 "', which is neither inside the .trz nor beside it");
    }
    in.info = probe_video(beside, beside);
    in.video_file = beside;
  } else if (auto [pattern, dir] = extract_image_sequence(path, entry, z.entries); dir) {
    in.info = probe_video(pattern, path + ":" + entry);
    // An image sequence has no frame rate of its own (FFmpeg's image reader says 25 whatever
    // was filmed): the project's frame duration is the clip's.
    in.info.fps = 0;
    in.temp_owner = dir;
  } else {
    auto temp = make_temp_file(lower_extension(entry));
    io::extract_zip_entry(path, entry, temp->path);
    in.info = probe_video(temp->path, path + ":" + entry);
    in.temp_owner = temp;
  }
  apply_project(in, p, o);
  return in;
}

}  // namespace

VideoInput open_input(const std::string& path, const SourceOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  const std::string ext = lower_extension(path);
  if (ext == ".trk") return open_trk(path, options);
  if (ext == ".trz") return open_trz(path, options);
  return open_plain(path, options);
}

// ---------------------------------------------------------------------------------------

struct FrameReader::Impl {
  VideoInput input;  // a copy: keeps a temporary video alive while frames are read
  std::unique_ptr<VideoFileReader> cap;
  int next_index = 0;  // video index of the frame the next grab() returns
  int steps_done = 0;
  bool finished = false;
  double last_t = -INFINITY;  // s, the previous frame's time
  int timestamped = 0;        // frames whose time is their timestamp, not the frame grid's
  int first_timestamped = -1;
  double first_nominal = 0, first_stamp = 0;  // s, of that first frame
  std::vector<std::string> warnings;

  /// The time of the frame just decoded (docs/theory.md#video-input-and-the-track-video-workflow):
  /// the frame grid's t(index) until a frame's timestamp departs from it by more than a
  /// quarter of a frame (a variable-frame-rate video: phones drop and stretch frames); from
  /// that frame on, every frame's timestamp. (Below a quarter frame the grid is the better
  /// clock: Matroska rounds timestamps to 1 ms, a third of a millisecond off at 30 fps.)
  double frame_time(int index) {
    const double nominal = input.time.t(index);
    if (!input.frame_times_from_timestamps) return nominal;
    const double ms = cap->get(cv::CAP_PROP_POS_MSEC);
    const double stamp = (input.time.start_time_s + ms / 1000) * input.time.time_scale;
    const double tol = 0.25 * input.time.real_frame_s();
    if (!std::isfinite(ms) || !(stamp > last_t)) return nominal;
    if (timestamped == 0 && !(std::abs(stamp - nominal) > tol)) return nominal;
    if (timestamped++ == 0) {
      first_timestamped = index;
      first_nominal = nominal;
      first_stamp = stamp;
    }
    return stamp;
  }

  void note_timestamps() {
    if (timestamped == 0 || !warnings.empty()) return;
    warnings.push_back("variable frame rate: " + std::to_string(timestamped) +
                       " frame(s) take their timestamps, not the average frame time's grid (from frame " +
                       std::to_string(first_timestamped) + " at t = " + io::format_number(first_stamp) +
                       " s, not " + io::format_number(first_nominal) + " s); give " + field("fps") +
                       " to impose a constant rate");
  }

  /// End of the decodable frames at `needed`: a clip that asks for more, or a video that
  /// stops well short of what its container announced, is truncated.
  bool end(int needed) {
    finished = true;
    const std::string& where = input.video_file.empty() ? input.input : input.video_file;
    if (input.clip.step_count > 0) {
      throw InputError(where, "the video ends after " + std::to_string(next_index) +
                                  " frame(s) but the clip needs frame " + std::to_string(needed) +
                                  " (truncated video?)");
    }
    if (steps_done == 0) {
      throw InputError(where, "the clip starts at frame " + std::to_string(input.clip.start_frame) +
                                  " but the video ends after " + std::to_string(next_index) + " frame(s)");
    }
    // containers estimate their frame count (duration x rate); a shortfall of more than a
    // few frames and 2 % is a file cut short, not an estimate
    const int announced = input.info.frame_count;
    if (announced > 0 && next_index < announced - std::max(3, announced / 50)) {
      throw InputError(where, "decoding stopped after " + std::to_string(next_index) +
                                  " of the " + std::to_string(announced) +
                                  " frames the file announces (truncated or corrupt video?)");
    }
    return false;
  }
};

FrameReader::FrameReader(const VideoInput& input) : impl_(std::make_unique<Impl>()) {
  quiet_decoder_logs();
  impl_->input = input;
  impl_->cap = open_video_file(input.info.path);
  if (!impl_->cap) {
    throw InputError(input.input, "cannot be decoded as a video");
  }
}

FrameReader::~FrameReader() = default;

bool FrameReader::next(Frame& frame) {
  Impl& m = *impl_;
  const Clip& clip = m.input.clip;
  if (m.finished || (clip.step_count > 0 && m.steps_done >= clip.step_count)) {
    m.note_timestamps();
    return false;
  }
  const int target = clip.start_frame + m.steps_done * clip.step_size;
  try {
    while (m.next_index < target) {  // frames outside the clip: demuxed, never converted
      if (!m.cap->grab()) return m.end(target);
      ++m.next_index;
    }
    // a fresh Mat each frame: trackers may keep (shallow copies of) earlier frames, which
    // decoding into a reused buffer would overwrite
    cv::Mat bgr;
    if (!m.cap->read(bgr) || bgr.empty()) {
      m.note_timestamps();
      return m.end(target);
    }
    frame.bgr = bgr;
  } catch (const cv::Exception&) {
    throw InputError(m.input.input, "decoding failed at frame " + std::to_string(target));
  }
  ++m.next_index;
  ++m.steps_done;
  frame.index = target;
  frame.t = m.last_t = m.frame_time(target);
  frame.gray = cv::Mat();  // each tracker converts the windows it reads (gray_region)
  return true;
}

const std::vector<std::string>& FrameReader::warnings() const { return impl_->warnings; }

int FrameReader::expected_steps() const {
  const Clip& c = impl_->input.clip;
  if (c.step_count > 0) return c.step_count;
  const int n = impl_->input.info.frame_count - c.start_frame;
  return n > 0 ? (n + c.step_size - 1) / c.step_size : 0;
}

}  // namespace tribolab::video
