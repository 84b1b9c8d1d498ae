// The studio's request handling (docs/design.md#studio): routing, the security rules
// (guard.hpp), the checks of every parameter and JSON body, and the answers, as one function
// from a Request to a Response that never throws. What the requests do to a project is a
// Backend (workbench.hpp is the real one), so the handler is tested and fuzzed without
// OpenCV, tracking or sockets.
#pragma once

#include "studio/guard.hpp"
#include "studio/http.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::studio {

/// Calibration of a plain video as the page sets it (image pixels: x right, y down).
struct CalibrationInput {
  std::optional<std::array<double, 4>> stick_px;  ///< two ends of a stick X1,Y1,X2,Y2, px
  double stick_length_m = 0;                      ///< its length, m (> 0 with a stick)
  std::optional<std::array<double, 2>> origin_px; ///< world origin in the image, px
  double axes_deg = 0;                            ///< world x-axis counter-clockwise from the image x-axis, deg (0: the video's)
  std::optional<double> fps;                      ///< frames per second (unset: the container's), 1/s
  double time_scale = 1;                          ///< real s per video s (slow motion 240 -> 30 fps: 0.125)
};

/// The user's position of a track in one frame (a dragged point): the track passes there.
struct TrackMark {
  int frame = 0;              ///< the video's frame index
  double x_px = 0, y_px = 0;  ///< image px
};

/// A click on an object: follow it from there.
struct TrackStart {
  std::string name = "ball";  ///< track name: letters, digits, '_' or '-'
  std::string kind = "point"; ///< "point" (the path tracker) or "ellipse" (a ball contrasting with its background)
  double x_px = 0, y_px = 0;  ///< the click, image px
  int frame = 0;              ///< the video's frame index clicked on
  std::vector<TrackMark> marks;  ///< corrections, by frame (app::TrackVideoOptions::mark)
};

/// A request to set (a dragged or placed point) or remove the mark of a track in one frame.
struct MarkInput {
  std::string track;          ///< the track's name (an ellipse's: its centre's)
  int frame = 0;              ///< the video's frame index
  bool remove = false;        ///< true: remove the frame's mark (x_px, y_px unused)
  double x_px = 0, y_px = 0;  ///< image px
};

/// The page's JSON (also the autosave's) as typed values; InputError naming the key for a
/// missing or mistyped one (a non-finite number, a name with other characters than letters,
/// digits, '_' and '-').
CalibrationInput calibration_from_json(const nlohmann::json& j);
TrackStart start_from_json(const nlohmann::json& j);
MarkInput mark_from_json(const nlohmann::json& j);
nlohmann::json to_json(const CalibrationInput& c);
nlohmann::json to_json(const TrackStart& s);

/// What the requests do to the project. Throws tribolab::InputError for input the user can
/// change (answered 400 with its message); anything else thrown is answered 500.
class Backend {
 public:
  virtual ~Backend() = default;
  virtual nlohmann::json files() = 0;                                    ///< videos and projects in the folder
  virtual nlohmann::json open(const std::filesystem::path& file) = 0;    ///< a confined, existing file
  virtual std::string frame_jpeg(int step) = 0;                          ///< the clip's step-th frame as JPEG
  virtual nlohmann::json calibrate(const CalibrationInput& c) = 0;
  virtual nlohmann::json track(const TrackStart& start) = 0;
  /// Sets or removes a mark and re-tracks that track (the state, with the new track).
  virtual nlohmann::json mark(const MarkInput& mark) = 0;
  /// Tracks every track again from the video, so that each mark's look is searched for in the
  /// frames around it (a mark's quick re-tracking does not: the state's `looks_pending`).
  virtual nlohmann::json retrack() = 0;
  virtual nlohmann::json forms() = 0;                                    ///< the analyses' declared fields
  /// Runs an offered analysis on the open file's tracks and, for a series, on those of the
  /// other files named (confined, existing files of the folder), in that order after it.
  virtual nlohmann::json analyze(const std::string& command, const nlohmann::json& values,
                                 const std::vector<std::filesystem::path>& series) = 0;
  /// The last analysis's HTML report, as written beside the file (InputError when there is none).
  virtual std::string report_html() = 0;
  virtual nlohmann::json state() = 0;                                    ///< the project as autosaved
  /// The long action under way: {"running", "action", "done", "expected"} (frames). Called
  /// while another thread runs an action: must be thread-safe.
  virtual nlohmann::json progress() = 0;
  /// Asks the long action under way to stop (it ends with an InputError, the project as
  /// before it); nothing when none runs. Thread-safe as progress().
  virtual nlohmann::json cancel() = 0;
};

/// What the page is made of: the HTML+JS page and Plotly.js (page.hpp, report/embedded.hpp).
struct Assets {
  std::string_view page_html;
  std::string_view plotly_js;
};

class Handler {
 public:
  /// `root`: the folder the studio serves (made canonical here; must exist).
  Handler(const std::filesystem::path& root, AccessRules rules, Assets assets, Backend& backend);
  /// The answer to `request`; never throws. One request reaches the backend at a time, but
  /// progress and cancel, which reach it while an action runs; an action (open, upload, calibrate,
  /// track, mark, analyze) asked while another runs is answered 409 at once, not queued.
  /// More requests than the rules' rate are answered 429.
  ///
  /// `POST /api/upload?name=NAME` with the file's bytes as the body (not a form) saves them
  /// in the folder's `uploads/` under a safe, free name (upload.hpp) as they arrive, then opens
  /// the file as `POST /api/open` would; it is an action (409 while another runs). Refused
  /// before a byte is written: a name the studio does not open (415), a declared size over
  /// AccessRules::max_upload_bytes (413) or over the disk's free space (507); while
  /// writing: more bytes than the limit (413), a full or unwritable disk (507), a connection
  /// cut (400); nothing is left behind by a refused or failed upload.
  Response handle(const Request& request);
  const std::filesystem::path& root() const { return root_; }
  const AccessRules& rules() const { return rules_; }

 private:
  Response route(const Request& request, const Target& target);
  Response upload(const Request& request, const Target& target);
  /// The body of a request to a route other than the upload, at most max_body_bytes (413).
  std::string small_body(const Request& request) const;
  /// Marks an action as running until the returned guard ends; 409 when one already runs.
  struct ActionClaim {
    std::atomic<bool>* flag = nullptr;
    ActionClaim() = default;
    explicit ActionClaim(std::atomic<bool>* f) : flag(f) {}
    ActionClaim(ActionClaim&& o) noexcept : flag(o.flag) { o.flag = nullptr; }
    ActionClaim& operator=(ActionClaim&&) = delete;
    ~ActionClaim() {
      if (flag) *flag = false;
    }
  };
  ActionClaim claim_action();
  std::filesystem::path root_;
  AccessRules rules_;
  Assets assets_;
  Backend& backend_;
  std::mutex backend_mutex_;
  std::atomic<bool> action_running_{false};
  std::atomic<bool> uploading_{false};  ///< an upload's bytes are arriving (the action running)
  std::mutex rate_mutex_;
  double tokens_ = 0;                                   ///< the rate limit's bucket
  std::chrono::steady_clock::time_point refilled_;
};

}  // namespace tribolab::studio
