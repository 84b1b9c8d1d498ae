#include "studio/handler.hpp"

#include "numerics/error.hpp"
#include "studio/upload.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace tribolab::studio {

namespace {

using nlohmann::json;

/// A request the handler refuses before the backend sees it.
struct BadRequest {
  int status;
  std::string message;
};

json object_body(const Request& r) {
  json j = json::parse(r.body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw InputError("the request body is not valid JSON");
  if (!j.is_object()) throw InputError("the request body must be a JSON object");
  return j;
}

/// The Content-Length header as a number; nullopt when absent (a chunked body). 400 when it is
/// not a plain decimal number.
std::optional<std::uint64_t> declared_length(const Request& r) {
  const auto v = r.header("Content-Length");
  if (!v) return std::nullopt;
  if (v->empty() || v->size() > 19 || v->find_first_not_of("0123456789") != std::string::npos)
    throw BadRequest{400, "the Content-Length header is not a number of bytes"};
  return std::stoull(*v);
}

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

double number(const json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) throw InputError(std::string("'") + key + "' must be a number");
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw InputError(std::string("'") + key + "' must be finite");
  return v;
}

std::optional<double> optional_number(const json& j, const char* key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  return number(j, key);
}

template <std::size_t N>
std::optional<std::array<double, N>> optional_numbers(const json& j, const char* key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  const json& a = j[key];
  if (!a.is_array() || a.size() != N)
    throw InputError(std::string("'") + key + "' must be a list of " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) {
    if (!a[i].is_number() || !std::isfinite(a[i].get<double>()))
      throw InputError(std::string("'") + key + "' must be a list of " + std::to_string(N) + " finite numbers");
    out[i] = a[i].get<double>();
  }
  return out;
}

std::string text(const json& j, const char* key, std::string fallback) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return fallback;
  if (!it->is_string()) throw InputError(std::string("'") + key + "' must be text");
  return it->get<std::string>();
}

int integer(double v, const char* key) {
  if (v != std::floor(v) || std::abs(v) > 1e9) throw InputError(std::string("'") + key + "' must be a whole number");
  return static_cast<int>(v);
}

}  // namespace

CalibrationInput calibration_from_json(const json& j) {
  CalibrationInput c;
  c.stick_px = optional_numbers<4>(j, "stick");
  c.stick_length_m = optional_number(j, "length").value_or(0);
  c.origin_px = optional_numbers<2>(j, "origin");
  c.axes_deg = optional_number(j, "axes_deg").value_or(0);
  c.fps = optional_number(j, "fps");
  c.time_scale = optional_number(j, "time_scale").value_or(1);
  return c;
}

namespace {

/// `text` with the folder's own place on disk left out of the paths in it: the page names a
/// file as the user chose it, relative to the folder (a message like "/home/ann/lab/clip.mp4:
/// no frame" says where the folder is, which the page never needs to show).
std::string within_folder(std::string text, const std::filesystem::path& root) {
  std::string prefix = root.string();
  if (prefix.empty()) return text;
  if (prefix.back() != '/') prefix += '/';
  for (std::size_t p = text.find(prefix); p != std::string::npos; p = text.find(prefix, p)) text.erase(p, prefix.size());
  return text;
}

std::string track_name(const json& j, const char* key, const std::string& fallback) {
  const std::string name = text(j, key, fallback);
  if (name.empty() || name.size() > 40) throw InputError(std::string("'") + key + "' must have 1 to 40 characters");
  for (char ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-')
      throw InputError(std::string("'") + key + "' may hold only letters, digits, '_' and '-'");
  return name;
}

int frame_number(const json& j) {
  const int f = integer(number(j, "frame"), "frame");
  if (f < 0) throw InputError("'frame' must not be negative");
  return f;
}

}  // namespace

TrackStart start_from_json(const json& j) {
  TrackStart s;
  s.name = track_name(j, "name", s.name);
  s.kind = text(j, "kind", s.kind);
  if (s.kind != "point" && s.kind != "ellipse") throw InputError("'kind' must be point or ellipse");
  s.x_px = number(j, "x");
  s.y_px = number(j, "y");
  s.frame = integer(number(j, "frame"), "frame");
  if (j.contains("marks") && !j["marks"].is_null()) {
    if (!j["marks"].is_array() || j["marks"].size() > 100000) throw InputError("'marks' must be a list of {frame, x, y}");
    for (const json& m : j["marks"]) {
      if (!m.is_object()) throw InputError("'marks' must be a list of {frame, x, y}");
      s.marks.push_back({frame_number(m), number(m, "x"), number(m, "y")});
    }
  }
  return s;
}

MarkInput mark_from_json(const json& j) {
  MarkInput m;
  m.track = track_name(j, "track", "");
  m.frame = frame_number(j);
  const auto remove = j.find("remove");
  if (remove != j.end() && !remove->is_null() && !remove->is_boolean()) throw InputError("'remove' must be true or false");
  m.remove = remove != j.end() && remove->is_boolean() && remove->get<bool>();
  if (!m.remove) {
    m.x_px = number(j, "x");
    m.y_px = number(j, "y");
  }
  return m;
}

json to_json(const CalibrationInput& c) {
  return {{"stick", c.stick_px ? json(*c.stick_px) : json(nullptr)},
          {"length", c.stick_length_m},
          {"origin", c.origin_px ? json(*c.origin_px) : json(nullptr)},
          {"axes_deg", c.axes_deg},
          {"fps", c.fps ? json(*c.fps) : json(nullptr)},
          {"time_scale", c.time_scale}};
}

json to_json(const TrackStart& s) {
  json marks = json::array();
  for (const TrackMark& m : s.marks) marks.push_back({{"frame", m.frame}, {"x", m.x_px}, {"y", m.y_px}});
  return {{"name", s.name}, {"kind", s.kind}, {"x", s.x_px}, {"y", s.y_px}, {"frame", s.frame}, {"marks", marks}};
}

Handler::Handler(const std::filesystem::path& root, AccessRules rules, Assets assets, Backend& backend)
    : root_(std::filesystem::canonical(root)), rules_(std::move(rules)), assets_(assets), backend_(backend),
      tokens_(rules_.request_burst), refilled_(std::chrono::steady_clock::now()) {}

Response Handler::handle(const Request& request) {
  {
    // The rate limit first: a flood (of good or bad requests) costs one comparison each.
    std::lock_guard lock(rate_mutex_);
    const auto now = std::chrono::steady_clock::now();
    tokens_ = std::min(rules_.request_burst,
                       tokens_ + rules_.requests_per_second * std::chrono::duration<double>(now - refilled_).count());
    refilled_ = now;
    if (tokens_ < 1) {
      return json_error(429, "too many requests: the studio answers at most " +
                                 std::to_string(static_cast<long>(rules_.requests_per_second)) + " a second");
    }
    tokens_ -= 1;
  }
  try {
    const auto target = parse_target(request.target);
    if (!target) return json_error(400, "the request target is malformed");
    if (auto refused = refuse(request, *target, rules_)) return *refused;
    if (target->path == "/api/upload") return upload(request, *target);
    if (!request.read_body && request.body.size() <= rules_.max_body_bytes) return route(request, *target);
    Request read{request.method, request.target, request.headers, small_body(request), nullptr};
    return route(read, *target);
  } catch (const BadRequest& e) {
    return json_error(e.status, within_folder(e.message, root_));
  } catch (const UploadError& e) {
    return json_error(e.status, within_folder(e.what(), root_));
  } catch (const InputError& e) {
    return json_error(400, within_folder(e.what(), root_));
  } catch (const std::exception& e) {
    return json_error(500, within_folder(std::string("internal error: ") + e.what(), root_));
  } catch (...) {
    return json_error(500, "internal error");
  }
}

std::string Handler::small_body(const Request& request) const {
  const std::size_t max = rules_.max_body_bytes;
  const auto too_large = [&](const std::string& size) {
    return BadRequest{413, "the request body has " + size + " bytes, more than the " + std::to_string(max) + " allowed"};
  };
  if (!request.read_body) {
    if (request.body.size() > max) throw too_large(std::to_string(request.body.size()));
    return request.body;
  }
  if (const auto n = declared_length(request); n && *n > max) throw too_large(std::to_string(*n));
  std::string body;
  bool over = false;
  const bool read = request.read_body([&](std::string_view piece) {
    if (body.size() + piece.size() > max) return !(over = true);
    body.append(piece);
    return true;
  });
  if (over) throw BadRequest{413, "the request body is longer than the " + std::to_string(max) + " bytes allowed"};
  if (!read) throw BadRequest{400, "the request body was cut off"};
  return body;
}

Handler::ActionClaim Handler::claim_action() {
  bool idle = false;
  if (!action_running_.compare_exchange_strong(idle, true)) {
    // While a file is sent the backend runs nothing: the upload is named by the handler.
    std::string what = uploading_ ? "uploading a file" : backend_.progress().value("action", std::string());
    if (what.empty()) what = "an action";
    throw BadRequest{409, "another action is running (" + what + "): wait for it to end, or cancel it (POST /api/cancel)"};
  }
  return ActionClaim(&action_running_);
}

Response Handler::upload(const Request& request, const Target& target) {
  if (request.method != "POST") throw BadRequest{405, "method " + request.method + " is not allowed on /api/upload"};
  const std::string given = target.param("name").value_or("");
  const std::string name = upload_name(given);
  std::string type = request.header("Content-Type").value_or("");
  std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (type.rfind("multipart/", 0) == 0)
    throw UploadError(415, "send the file's bytes as the request body (as the page does), not as a form (" + type + ")");
  const std::uint64_t max = rules_.max_upload_bytes;
  const auto declared = declared_length(request);
  const auto too_large = [&](const std::string& size) {  // "has 3000.0 MB, more than", "is longer than"
    return UploadError(413, "'" + given + "' " + size + " the studio takes (" + megabytes(max) +
                                "): cut the clip, or put it in the studio's folder and open it from there");
  };
  if (declared && *declared > max) throw too_large("has " + megabytes(*declared) + ", more than");
  const ActionClaim claim = claim_action();
  struct Sending {
    std::atomic<bool>& flag;
    explicit Sending(std::atomic<bool>& f) : flag(f) { flag = true; }
    ~Sending() { flag = false; }
  } sending(uploading_);
  UploadFile file(root_);
  if (declared && *declared > file.available_bytes())
    throw UploadError(507, "'" + given + "' has " + megabytes(*declared) + " but the disk has " +
                               megabytes(file.available_bytes()) + " free: free some space");
  bool over = false;
  std::optional<UploadError> failed;
  const auto sink = [&](std::string_view piece) {
    if (file.size() + piece.size() > max) return !(over = true);
    try {
      file.write(piece);
    } catch (const UploadError& e) {
      failed = e;
      return false;
    }
    return true;
  };
  const bool read = request.read_body ? request.read_body(sink) : sink(request.body);
  if (failed) throw *failed;
  if (over) throw too_large("is longer than");
  if (!read) throw UploadError(400, "the upload of '" + given + "' was cut off after " + megabytes(file.size()) + ": nothing was saved");
  if (file.size() == 0) throw UploadError(400, "'" + given + "' is empty: nothing was saved");
  const std::string saved = file.commit(name);
  uploading_ = false;  // now the backend opens it, and names that action itself
  const Confined c = confine(root_, saved);
  if (!c.problem.empty()) throw BadRequest{403, c.problem};
  std::lock_guard lock(backend_mutex_);
  json state;
  try {
    state = backend_.open(c.path);
  } catch (const InputError& e) {
    // The page is told the folder's name for the file, not where the folder is on the disk.
    std::string why = e.what();
    const std::string absolute = c.path.string();
    for (auto at = why.find(absolute); at != std::string::npos; at = why.find(absolute, at + saved.size()))
      why.replace(at, absolute.size(), saved);
    throw InputError(saved + " is saved, but the studio cannot open it: " + why);
  }
  state["uploaded"] = {{"file", saved}, {"bytes", file.size()}, {"name", given}};
  return json_ok(state);
}

Response Handler::route(const Request& request, const Target& target) {
  const std::string& path = target.path;
  const bool get = request.method == "GET", post = request.method == "POST";
  auto need = [&](bool ok) {
    if (!ok) throw BadRequest{405, "method " + request.method + " is not allowed on " + path};
  };
  if (path == "/" || path == "/index.html") {
    need(get);
    return {200, "text/html; charset=utf-8", std::string(assets_.page_html)};
  }
  if (path == "/plotly.js") {
    need(get);
    return {200, "text/javascript; charset=utf-8", std::string(assets_.plotly_js)};
  }
  if (path.rfind("/api/", 0) != 0) return json_error(404, "no such page: " + path);

  // While an action runs: how far it is, and stopping it (no lock: the backend's are thread-safe).
  if (path == "/api/progress") {
    need(get);
    return json_ok(backend_.progress());
  }
  if (path == "/api/cancel") {
    need(post);
    return json_ok(backend_.cancel());
  }
  // One action at a time: another asked meanwhile is refused, not queued behind it.
  const bool action = path == "/api/open" || path == "/api/calibration" || path == "/api/track" ||
                      path == "/api/mark" || path == "/api/retrack" || path == "/api/analyze";
  const ActionClaim running = action && request.method == "POST" ? claim_action() : ActionClaim();
  std::lock_guard lock(backend_mutex_);
  if (path == "/api/files") {
    need(get);
    // What the page checks before sending a file (the server checks again).
    json listing = backend_.files();
    listing["upload"] = {{"folder", std::string(kUploadFolder)}, {"max_bytes", rules_.max_upload_bytes},
                         {"extensions", openable_extensions()}};
    return json_ok(listing);
  }
  if (path == "/api/state") {
    need(get);
    return json_ok(backend_.state());
  }
  if (path == "/api/forms") {
    need(get);
    return json_ok(backend_.forms());
  }
  if (path == "/api/report") {
    need(get);
    return {200, "text/html; charset=utf-8", backend_.report_html()};
  }
  if (path == "/api/frame") {
    need(get);
    const auto i = target.param("i");
    if (!i || i->empty() || i->size() > 9 || i->find_first_not_of("0123456789") != std::string::npos)
      throw BadRequest{400, "'i' must be a frame step, a whole number >= 0"};
    return {200, "image/jpeg", backend_.frame_jpeg(std::stoi(*i))};
  }
  if (path == "/api/open") {
    need(post);
    const json body = object_body(request);
    const Confined c = confine(root_, text(body, "file", ""));
    if (!c.problem.empty()) throw BadRequest{403, c.problem};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(c.path, ec)) throw BadRequest{404, "no such file in the folder: " + text(body, "file", "")};
    return json_ok(backend_.open(c.path));
  }
  if (path == "/api/calibration") {
    need(post);
    return json_ok(backend_.calibrate(calibration_from_json(object_body(request))));
  }
  if (path == "/api/track") {
    need(post);
    return json_ok(backend_.track(start_from_json(object_body(request))));
  }
  if (path == "/api/mark") {
    need(post);
    return json_ok(backend_.mark(mark_from_json(object_body(request))));
  }
  if (path == "/api/retrack") {
    need(post);
    return json_ok(backend_.retrack());
  }
  if (path == "/api/analyze") {
    need(post);
    const json body = object_body(request);
    const std::string command = text(body, "command", "");
    const json values = body.contains("values") ? body["values"] : json::object();
    if (!values.is_object()) throw BadRequest{400, "'values' must be a JSON object"};
    // A series: the other videos whose tracks join the open one's, each a file of the folder.
    std::vector<std::filesystem::path> series;
    if (body.contains("series") && !body["series"].is_null()) {
      const json& names = body["series"];
      if (!names.is_array() || names.size() > 1000) throw BadRequest{400, "'series' must be a list of file names"};
      for (const json& name : names) {
        if (!name.is_string()) throw BadRequest{400, "'series' must be a list of file names"};
        const Confined c = confine(root_, name.get<std::string>());
        if (!c.problem.empty()) throw BadRequest{403, c.problem};
        std::error_code ec;
        if (!std::filesystem::is_regular_file(c.path, ec))
          throw BadRequest{404, "no such file in the folder: " + name.get<std::string>()};
        series.push_back(c.path);
      }
    }
    return json_ok(backend_.analyze(command, values, series));
  }
  return json_error(404, "no such route: " + path);
}

}  // namespace tribolab::studio
