// The studio's project (docs/cli.md#studio): the video or Tracker project opened from the
// folder, its frames as JPEG (decoded by OpenCV once, on opening), the calibration and the
// clicks that start tracks, the tracks (app::track_video, the same workflow as `track video`)
// and the analyses (app::track_kinematics with a form made from its declared fields). Every
// action is saved to FILE.studio.json beside the file, and re-read when the file is opened.
#pragma once

#include "studio/handler.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace tribolab::video {
class TrackSession;
}

namespace tribolab::studio {

class Workbench : public Backend {
 public:
  /// `root`: the folder served (canonical, existing).
  explicit Workbench(std::filesystem::path root);

  nlohmann::json files() override;
  nlohmann::json open(const std::filesystem::path& file) override;
  std::string frame_jpeg(int step) override;
  nlohmann::json calibrate(const CalibrationInput& c) override;
  nlohmann::json track(const TrackStart& start) override;
  /// Sets or removes a mark of a track (on its start frame: moves the start) and re-tracks.
  nlohmann::json mark(const MarkInput& mark) override;
  /// Tracks every track again from the video (a fresh session): each mark's look searched for.
  nlohmann::json retrack() override;
  nlohmann::json forms() override;
  nlohmann::json analyze(const std::string& command, const nlohmann::json& values,
                         const std::vector<std::filesystem::path>& series = {}) override;
  std::string report_html() override;
  nlohmann::json state() override;
  nlohmann::json progress() override;
  nlohmann::json cancel() override;

  /// Largest total of the frames' JPEG bytes kept for one video (a longer video is refused).
  static constexpr std::size_t kMaxFrameBytes = std::size_t{1} << 30;

 private:
  std::filesystem::path beside(const std::string& suffix) const;  ///< FILE + suffix, in its folder
  std::string relative(const std::filesystem::path& p) const;     ///< p relative to the root
  void require_open() const;
  void run_tracks();   ///< tracks every start (app::track_video), writes CSV and .trk
  void autosave() const;
  /// Marks the action under way for progress() and cancel() (frames done of expected); throws
  /// InputError when cancelled (the action then leaves the project as it was).
  void step(int done, int expected);
  class Action;  ///< an action under way (RAII: progress() shows it while it lives)

  std::filesystem::path root_;
  std::filesystem::path file_;          ///< the opened video or project ("" before open)
  std::vector<std::string> jpeg_;       ///< per clip step
  nlohmann::json frames_ = nlohmann::json::array();  ///< per clip step: {frame, t}
  nlohmann::json video_;                ///< width, height, fps, frames
  int width_ = 0, height_ = 0;          ///< image size, px
  CalibrationInput calibration_;
  std::vector<TrackStart> starts_;
  nlohmann::json tracks_ = nlohmann::json::object();  ///< the last tracking, for the page
  nlohmann::json analysis_ = nullptr;   ///< the last analysis
  /// The last tracking, kept so that a mark re-tracks a path-tracked point without decoding
  /// the video again (app::TrackVideoOptions::session).
  std::shared_ptr<video::TrackSession> session_;
  /// The last tracking was a mark's quick one: a mark's look is not searched for yet (state's
  /// `looks_pending`; retrack() searches).
  bool looks_pending_ = false;
  std::vector<std::string> decoded_marks_;  ///< the marks (as `--mark` values) of the last decoding
  // The action under way, read by progress() and cancel() from the server's other threads.
  std::atomic<bool> running_{false}, cancel_{false};
  std::atomic<int> done_{0}, expected_{0};
  std::atomic<const char*> action_{""};
};

}  // namespace tribolab::studio
