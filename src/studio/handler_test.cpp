// The security rules and error answers of the request handler, without a socket: a recording
// backend stands for the workbench, so every refusal is checked to happen before any action.
#include "studio/handler.hpp"

#include "numerics/error.hpp"
#include "studio/upload.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <future>
#include <thread>
#include <fstream>
#include <iterator>
#include <cstdio>
#include <algorithm>
#include <vector>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

namespace tribolab::studio {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct RecordingBackend : Backend {
  int calls = 0;
  fs::path opened;
  json files() override { ++calls; return {{"files", json::array()}}; }
  json open(const fs::path& file) override { ++calls; opened = file; return {{"file", file.filename().string()}}; }
  std::string frame_jpeg(int step) override { ++calls; return "jpeg" + std::to_string(step); }
  json calibrate(const CalibrationInput& c) override { ++calls; return {{"length", c.stick_length_m}}; }
  json track(const TrackStart& s) override { ++calls; return {{"name", s.name}}; }
  MarkInput marked;
  json mark(const MarkInput& m) override { ++calls; marked = m; return {{"track", m.track}}; }
  int retracks = 0;
  json retrack() override { ++calls; ++retracks; return {{"looks_pending", false}}; }
  json forms() override { ++calls; return json::object(); }
  json analyze(const std::string& command, const json&, const std::vector<fs::path>& others) override {
    ++calls;
    series = others;
    return {{"command", command}};
  }
  std::vector<fs::path> series;
  std::string report_html() override { ++calls; return "<html>report</html>"; }
  json state() override { ++calls; return json::object(); }
  std::atomic<int> progress_calls{0}, cancel_calls{0};
  json progress() override { ++progress_calls; return {{"running", false}, {"action", "tracking"}}; }
  json cancel() override { ++cancel_calls; return {{"cancelling", false}}; }
};

const std::string kToken = std::string(64, 'a');
constexpr int kPort = 8765;

class HandlerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() / ("studio_handler_test_" + std::to_string(::getpid()));
    outside = root.string() + "_outside";
    fs::create_directories(root / "sub");
    fs::create_directories(outside);
    std::ofstream(root / "clip.avi") << "x";
    std::ofstream(root / "sub" / "inner.avi") << "x";
    std::ofstream(fs::path(outside) / "secret.avi") << "x";
    fs::create_symlink(fs::path(outside) / "secret.avi", root / "link.avi");
    fs::create_directory_symlink(outside, root / "linkdir");
    handler = std::make_unique<Handler>(root, AccessRules{kToken, kPort, 1000}, Assets{"<html>page</html>", "plotly"}, backend);
  }
  void TearDown() override {
    fs::remove_all(root);
    fs::remove_all(outside);
  }
  /// A request as the page sends it: right Host and Origin, the token in its header.
  Request good(std::string method, std::string target, std::string body = "") {
    return {std::move(method), std::move(target),
            {{"Host", "127.0.0.1:8765"}, {"Origin", "http://127.0.0.1:8765"}, {"X-Tribolab-Token", kToken}},
            std::move(body), nullptr};
  }
  static std::string error_of(const Response& r) { return json::parse(r.body).at("error").get<std::string>(); }

  fs::path root;
  std::string outside;
  RecordingBackend backend;
  std::unique_ptr<Handler> handler;
};

TEST_F(HandlerTest, GoodRequestsReachTheBackend) {
  EXPECT_EQ(handler->handle(good("GET", "/api/files")).status, 200);
  const Response page = handler->handle(good("GET", "/?token=" + kToken));
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.body, "<html>page</html>");
  EXPECT_EQ(handler->handle(good("GET", "/api/frame?i=7")).body, "jpeg7");
  const Response opened = handler->handle(good("POST", "/api/open", R"({"file": "sub/inner.avi"})"));
  EXPECT_EQ(opened.status, 200) << opened.body;
  EXPECT_EQ(backend.opened, fs::canonical(root / "sub" / "inner.avi"));
  const Response report = handler->handle(good("GET", "/api/report"));
  EXPECT_EQ(report.status, 200);
  EXPECT_EQ(report.content_type, "text/html; charset=utf-8");
  EXPECT_EQ(report.body, "<html>report</html>");
  EXPECT_EQ(handler->handle(good("POST", "/api/report", "{}")).status, 405);
  EXPECT_EQ(backend.calls, 4);
}

TEST_F(HandlerTest, TokenInTheQueryIsAcceptedAsInTheHeader) {
  Request r = good("GET", "/api/frame?i=2&token=" + kToken);
  r.headers.pop_back();  // no header token
  EXPECT_EQ(handler->handle(r).status, 200);
}

TEST_F(HandlerTest, MissingOrWrongTokenIsRefused) {
  for (const std::string& token : {std::string(), std::string(64, 'b'), kToken.substr(1), kToken + "a"}) {
    Request r = good("GET", "/api/files");
    r.headers.pop_back();
    if (!token.empty()) r.headers.emplace_back("x-tribolab-token", token);  // header names in any case
    const Response a = handler->handle(r);
    EXPECT_EQ(a.status, 403) << token;
    EXPECT_NE(error_of(a).find("token"), std::string::npos);
  }
  Request page = good("GET", "/");  // the page itself needs it too
  page.headers.pop_back();
  EXPECT_EQ(handler->handle(page).status, 403);
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(HandlerTest, HostOtherThanTheServersIsRefused) {
  // DNS rebinding: a page of evil.example whose name now resolves to 127.0.0.1 sends its own Host.
  for (const std::string host : {"evil.example:8765", "127.0.0.1:8766", "127.0.0.1", "localhost", "", "0.0.0.0:8765"}) {
    Request r = good("GET", "/api/files");
    r.headers[0].second = host;
    EXPECT_EQ(handler->handle(r).status, 403) << host;
  }
  Request none = good("GET", "/api/files");
  none.headers.erase(none.headers.begin());
  EXPECT_EQ(handler->handle(none).status, 403);
  Request local = good("GET", "/api/files");
  local.headers[0].second = "localhost:8765";
  local.headers[1].second = "http://localhost:8765";
  EXPECT_EQ(handler->handle(local).status, 200);
  EXPECT_EQ(backend.calls, 1);
}

TEST_F(HandlerTest, ForeignOriginIsRefused) {
  for (const std::string origin : {"http://evil.example", "http://127.0.0.1:8766", "https://127.0.0.1:8765", "null", ""}) {
    Request r = good("POST", "/api/track", R"({"x": 1, "y": 2, "frame": 0})");
    r.headers[1].second = origin;
    const Response a = handler->handle(r);
    EXPECT_EQ(a.status, 403) << origin;
    EXPECT_NE(error_of(a).find("Origin"), std::string::npos);
  }
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(HandlerTest, PathsOutsideTheFolderAreRefused) {
  for (const std::string& file : std::vector<std::string>{"../x.avi", "sub/../../x.avi", "sub/../clip.avi", "/etc/passwd", "link.avi",
                                 "linkdir/secret.avi", std::string("clip.avi\0x", 10), ""}) {
    const Response a = handler->handle(good("POST", "/api/open", json{{"file", file}}.dump()));
    EXPECT_EQ(a.status, 403) << file;
  }
  // Percent-encoded dots are decoded before routing, never reach the file system as a path.
  EXPECT_EQ(handler->handle(good("GET", "/%2e%2e/%2e%2e/etc/passwd")).status, 404);
  EXPECT_EQ(handler->handle(good("POST", "/api/open", R"({"file": "missing.avi"})")).status, 404);
  EXPECT_EQ(backend.calls, 0);
}

TEST(Confine, ResolvesInsideAndRefusesOutside) {
  const fs::path root = fs::canonical(fs::temp_directory_path());
  EXPECT_EQ(confine(root, "a/b.avi").path, root / "a" / "b.avi");  // need not exist yet
  EXPECT_FALSE(confine(root, "a/../../b").problem.empty());
  EXPECT_FALSE(confine(root, "/tmp/x").problem.empty());
  // A dangling symlink: weakly_canonical leaves it unresolved, inside; writing would create its target.
  const fs::path dangling = root / ("studio_dangling_" + std::to_string(::getpid()));
  fs::create_symlink("/nonexistent_dir_of_tribolab/x.csv", dangling);
  EXPECT_FALSE(confine(root, dangling.filename().string()).problem.empty());
  fs::remove(dangling);
}

TEST_F(HandlerTest, OversizedBodyIsRefused) {
  const Response a = handler->handle(good("POST", "/api/track", std::string(1001, ' ')));
  EXPECT_EQ(a.status, 413);
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(HandlerTest, MalformedJsonIsAnsweredNotCrashed) {
  for (const std::string body : {"{", "[1, 2]", "\"text\"", "{\"x\": \"1\", \"y\": 2, \"frame\": 0}",
                                 "{\"x\": 1, \"y\": 2, \"frame\": 0.5}", "{\"x\": 1e999, \"y\": 2, \"frame\": 0}",
                                 "{\"x\": 1, \"y\": 2, \"frame\": 0, \"name\": \"a b\"}",
                                 "{\"x\": 1, \"y\": 2, \"frame\": 0, \"kind\": \"square\"}", "\xff\xfe"}) {
    const Response a = handler->handle(good("POST", "/api/track", body));
    EXPECT_EQ(a.status, 400) << body;
    EXPECT_FALSE(error_of(a).empty());
  }
  EXPECT_EQ(handler->handle(good("POST", "/api/calibration", R"({"stick": [1, 2, 3]})")).status, 400);
  EXPECT_EQ(handler->handle(good("POST", "/api/calibration", R"({"axes_deg": "30"})")).status, 400);
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"values": 3})")).status, 400);
  EXPECT_EQ(handler->handle(good("GET", "/api/frame?i=-1")).status, 400);
  EXPECT_EQ(handler->handle(good("GET", "/api/frame?i=%zz")).status, 400);
  EXPECT_EQ(backend.calls, 0);
}

// The axes' angle the page sends after a drag: read, kept in the state and autosave, 0 when
// not given (the video's own).
TEST(CalibrationJson, ReadsAndWritesTheAxesAngle) {
  EXPECT_EQ(calibration_from_json(json::object()).axes_deg, 0);
  const CalibrationInput c = calibration_from_json({{"origin", {10, 20}}, {"axes_deg", -12.5}});
  EXPECT_EQ(c.axes_deg, -12.5);
  EXPECT_EQ(to_json(c)["axes_deg"], -12.5);
  EXPECT_EQ(calibration_from_json(to_json(c)).axes_deg, -12.5);
  EXPECT_THROW(calibration_from_json({{"axes_deg", {1, 2}}}), InputError);
}

// A series names other files of the folder, each confined as an opened file is.
TEST_F(HandlerTest, SeriesFilesAreConfinedToTheFolder) {
  const Response ok = handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": ["sub/inner.avi"]})"));
  EXPECT_EQ(ok.status, 200) << ok.body;
  EXPECT_EQ(backend.series, std::vector<fs::path>{fs::canonical(root / "sub" / "inner.avi")});
  const int calls = backend.calls;
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": ["../outside.avi"]})")).status, 403);
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": ["/etc/passwd"]})")).status, 403);
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": ["none.avi"]})")).status, 404);
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": "sub/inner.avi"})")).status, 400);
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"command": "c", "series": [1]})")).status, 400);
  EXPECT_EQ(backend.calls, calls);
}

TEST_F(HandlerTest, MarkRequestsAreCheckedBeforeTheBackend) {
  const Response set = handler->handle(good("POST", "/api/mark", R"({"track": "ball", "frame": 12, "x": 10.5, "y": 20})"));
  EXPECT_EQ(set.status, 200) << set.body;
  EXPECT_EQ(backend.marked.track, "ball");
  EXPECT_EQ(backend.marked.frame, 12);
  EXPECT_FALSE(backend.marked.remove);
  EXPECT_DOUBLE_EQ(backend.marked.x_px, 10.5);
  EXPECT_DOUBLE_EQ(backend.marked.y_px, 20);
  const Response removed = handler->handle(good("POST", "/api/mark", R"({"track": "ball", "frame": 12, "remove": true})"));
  EXPECT_EQ(removed.status, 200) << removed.body;
  EXPECT_TRUE(backend.marked.remove);
  EXPECT_EQ(backend.calls, 2);
  // NaN and an overflow are no JSON numbers; as text, a string, a fraction of a frame, a negative
  // frame, no track, a track name with a space, no position: each answered with its reason.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({"track": "ball", "frame": 3, "x": NaN, "y": 2})", "not valid JSON"},
      {R"({"track": "ball", "frame": 3, "x": "NaN", "y": 2})", "'x' must be a number"},
      {R"({"track": "ball", "frame": 3, "x": 1e999, "y": 2})", "not valid JSON"},  // an overflow is no JSON number
      {R"({"track": "ball", "frame": 2.5, "x": 1, "y": 2})", "'frame' must be a whole number"},
      {R"({"track": "ball", "frame": -1, "x": 1, "y": 2})", "'frame' must not be negative"},
      {R"({"frame": 3, "x": 1, "y": 2})", "'track' must have 1 to 40 characters"},
      {R"({"track": "a b", "frame": 3, "x": 1, "y": 2})", "'track' may hold only"},
      {R"({"track": "ball", "frame": 3})", "'x' must be a number"},
      {R"({"track": "ball", "frame": 3, "remove": "yes"})", "'remove' must be true or false"},
  };
  for (const auto& [body, message] : bad) {
    const Response a = handler->handle(good("POST", "/api/mark", body));
    EXPECT_EQ(a.status, 400) << body;
    EXPECT_NE(error_of(a).find(message), std::string::npos) << body << " -> " << error_of(a);
  }
  EXPECT_EQ(handler->handle(good("GET", "/api/mark")).status, 405);
  // The search for the marks' looks: an action of its own.
  EXPECT_EQ(handler->handle(good("POST", "/api/retrack", "{}")).status, 200);
  EXPECT_EQ(backend.retracks, 1);
  EXPECT_EQ(handler->handle(good("GET", "/api/retrack")).status, 405);
  EXPECT_EQ(backend.calls, 3);  // the two good marks and the search
}

TEST_F(HandlerTest, MoreRequestsThanTheRateAreAnswered429) {
  // 5 a second, a burst of 5: the sixth request in a row (microseconds apart) is refused,
  // whatever it is, before any other check; a moment later requests pass again.
  Handler limited(root, AccessRules{kToken, kPort, 1000, 5, 5}, Assets{"", ""}, backend);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(limited.handle(good("GET", "/api/files")).status, 200) << i;
  const Response refused = limited.handle(good("GET", "/api/files"));
  EXPECT_EQ(refused.status, 429);
  EXPECT_NE(error_of(refused).find("too many requests"), std::string::npos);
  EXPECT_EQ(limited.handle(Request{"GET", "/api/files", {}, "", nullptr}).status, 429);  // no token either
  EXPECT_EQ(backend.calls, 5);
  std::this_thread::sleep_for(std::chrono::milliseconds(450));  // 2 requests' worth
  EXPECT_EQ(limited.handle(good("GET", "/api/files")).status, 200);
}

TEST_F(HandlerTest, OneActionAtATimeWithProgressAndCancel) {
  // A tracking that runs until released: meanwhile another action is refused at once (409,
  // naming the action), progress and cancel are answered (they do not wait for it).
  struct Slow : RecordingBackend {
    std::promise<void> started, release;
    json track(const TrackStart& s) override {
      started.set_value();
      release.get_future().wait();
      return {{"name", s.name}};
    }
  } slow;
  Handler h(root, AccessRules{kToken, kPort, 1000}, Assets{"", ""}, slow);
  auto tracking = std::async(std::launch::async, [&] {
    return h.handle(good("POST", "/api/track", R"({"x": 1, "y": 2, "frame": 0})"));
  });
  slow.started.get_future().wait();
  const Response other = h.handle(good("POST", "/api/mark", R"({"track": "ball", "frame": 3, "x": 1, "y": 2})"));
  EXPECT_EQ(other.status, 409);
  EXPECT_NE(error_of(other).find("another action is running (tracking)"), std::string::npos) << error_of(other);
  EXPECT_EQ(h.handle(good("POST", "/api/open", R"({"file": "clip.avi"})")).status, 409);
  EXPECT_EQ(h.handle(good("GET", "/api/progress")).status, 200);
  EXPECT_EQ(h.handle(good("POST", "/api/cancel", "{}")).status, 200);
  EXPECT_EQ(slow.cancel_calls, 1);
  EXPECT_EQ(h.handle(good("GET", "/api/cancel")).status, 405);
  slow.release.set_value();
  EXPECT_EQ(tracking.get().status, 200);
  // Ended: the next action runs.
  EXPECT_EQ(h.handle(good("POST", "/api/mark", R"({"track": "ball", "frame": 3, "x": 1, "y": 2})")).status, 200);
}

TEST_F(HandlerTest, UnknownRouteAndWrongMethodAreAnswered) {
  EXPECT_EQ(handler->handle(good("GET", "/api/nothing")).status, 404);
  EXPECT_EQ(handler->handle(good("GET", "/etc/passwd")).status, 404);
  EXPECT_EQ(handler->handle(good("DELETE", "/api/files")).status, 405);
  EXPECT_EQ(handler->handle(good("GET", "/api/track")).status, 405);
  EXPECT_EQ(handler->handle(good("GET", "no-slash")).status, 400);
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(HandlerTest, BackendErrorsBecomeJsonAnswers) {
  struct Failing : RecordingBackend {
    json files() override { throw InputError("clip.avi", "not a video"); }
    json state() override { throw std::runtime_error("boom"); }
  } failing;
  Handler h(root, AccessRules{kToken, kPort, 1000}, Assets{"", ""}, failing);
  const Response input = h.handle(good("GET", "/api/files"));
  EXPECT_EQ(input.status, 400);
  EXPECT_EQ(error_of(input), "clip.avi: not a video");
  EXPECT_EQ(h.handle(good("GET", "/api/state")).status, 500);
}

// The backend names files by their full path (the video layer's messages); the page shows
// them relative to the folder, never where the folder is on disk.
TEST_F(HandlerTest, ErrorsNameFilesWithinTheFolder) {
  struct Refusing : RecordingBackend {
    json open(const fs::path& file) override { throw InputError(file.string(), "no frame could be decoded"); }
    json state() override { throw std::runtime_error("cannot read " + (root / "sub" / "x.trk").string()); }
    fs::path root;
  } refusing;
  refusing.root = fs::canonical(root);
  Handler h(root, AccessRules{kToken, kPort, 1000}, Assets{"", ""}, refusing);
  const Response opened = h.handle(good("POST", "/api/open", R"({"file": "sub/inner.avi"})"));
  EXPECT_EQ(opened.status, 400);
  EXPECT_EQ(error_of(opened), "sub/inner.avi: no frame could be decoded");
  const Response state = h.handle(good("GET", "/api/state"));
  EXPECT_EQ(state.status, 500);
  EXPECT_EQ(error_of(state), "internal error: cannot read sub/x.trk");
}

// Uploads (POST /api/upload?name=NAME, the file's bytes as the body): every rule, then a good
// upload that is opened as a file chosen from the folder.
class StudioUploadTest : public HandlerTest {
 protected:
  Request upload(const std::string& name, std::string body) {
    std::string target = "/api/upload?name=";
    for (unsigned char c : name) {  // percent-encoded, as the page's encodeURIComponent
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      target += std::isalnum(c) ? std::string(1, static_cast<char>(c)) : std::string(hex);
    }
    return good("POST", target, std::move(body));
  }
  /// The files under uploads/ (none when it does not exist).
  std::vector<std::string> uploaded() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(root / "uploads", ec)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

TEST_F(StudioUploadTest, AGoodUploadIsSavedInUploadsAndOpened) {
  const std::string bytes("RIFF\0\x01\x02video bytes", 18);
  const Response a = handler->handle(upload("throw.avi", bytes));
  ASSERT_EQ(a.status, 200) << a.body;
  EXPECT_EQ(read(root / "uploads" / "throw.avi"), bytes);
  EXPECT_EQ(backend.opened, fs::canonical(root / "uploads" / "throw.avi"));  // opened as if chosen from the folder
  const json j = json::parse(a.body);
  EXPECT_EQ(j["uploaded"]["file"], "uploads/throw.avi");
  EXPECT_EQ(j["uploaded"]["bytes"], bytes.size());
  EXPECT_EQ(j["file"], "throw.avi");  // the backend's answer (the recording backend's: the name)
  EXPECT_EQ(uploaded(), std::vector<std::string>{"throw.avi"});  // no temporary file left
  // The listing tells the page the rules it checks before sending.
  const json files = json::parse(handler->handle(good("GET", "/api/files")).body);
  EXPECT_EQ(files["upload"]["max_bytes"], AccessRules{}.max_upload_bytes);
  EXPECT_EQ(files["upload"]["folder"], "uploads");
  EXPECT_EQ(files["upload"]["extensions"].size(), openable_extensions().size());
}

TEST_F(StudioUploadTest, AnExistingNameIsNeverReplaced) {
  ASSERT_EQ(handler->handle(upload("clip.avi", "one")).status, 200);
  const Response again = handler->handle(upload("clip.avi", "two"));
  ASSERT_EQ(again.status, 200) << again.body;
  EXPECT_EQ(json::parse(again.body)["uploaded"]["file"], "uploads/clip-2.avi");
  EXPECT_EQ(read(root / "uploads" / "clip.avi"), "one");
  EXPECT_EQ(read(root / "uploads" / "clip-2.avi"), "two");
  EXPECT_EQ(backend.opened, fs::canonical(root / "uploads" / "clip-2.avi"));
}

TEST_F(StudioUploadTest, ATokenAHostAnOriginAndTheRateAreNeededAsEverywhere) {
  Request no_token = upload("clip.avi", "x");
  no_token.headers.pop_back();
  EXPECT_EQ(handler->handle(no_token).status, 403);
  Request foreign = upload("clip.avi", "x");
  foreign.headers[1].second = "http://evil.example";  // a page of another site posting a file
  EXPECT_EQ(handler->handle(foreign).status, 403);
  Request rebound = upload("clip.avi", "x");
  rebound.headers[0].second = "evil.example:8765";
  EXPECT_EQ(handler->handle(rebound).status, 403);
  EXPECT_FALSE(fs::exists(root / "uploads"));
  EXPECT_EQ(backend.calls, 0);
  EXPECT_EQ(handler->handle(good("GET", "/api/upload?name=clip.avi")).status, 405);
  // The rate limit counts an upload as any request, before anything is written.
  Handler limited(root, AccessRules{kToken, kPort, 1000, 1, 1}, Assets{"", ""}, backend);
  EXPECT_EQ(limited.handle(good("GET", "/api/state")).status, 200);
  EXPECT_EQ(limited.handle(upload("clip.avi", "x")).status, 429);
  EXPECT_FALSE(fs::exists(root / "uploads"));
}

TEST_F(StudioUploadTest, BadNamesAndPathsStayInUploads) {
  // Path parts are dropped: the file lands in uploads/ under its last component.
  const Response up = handler->handle(upload("../../escape.avi", "x"));
  ASSERT_EQ(up.status, 200) << up.body;
  EXPECT_EQ(json::parse(up.body)["uploaded"]["file"], "uploads/escape.avi");
  EXPECT_FALSE(fs::exists(root.parent_path() / "escape.avi"));
  EXPECT_EQ(handler->handle(upload("sub/../..\\..\\.hidden\x01name.avi", "x")).status, 200);
  EXPECT_EQ(uploaded(), (std::vector<std::string>{"escape.avi", "hidden_name.avi"}));
  // Nothing usable: refused, nothing written.
  EXPECT_EQ(handler->handle(good("POST", "/api/upload", "x")).status, 400);  // no name
  EXPECT_EQ(handler->handle(upload("..", "x")).status, 415);
  EXPECT_EQ(handler->handle(upload("../", "x")).status, 415);
  EXPECT_EQ(uploaded().size(), 2u);
}

TEST_F(StudioUploadTest, OnlyFilesTheStudioOpensAreTaken) {
  for (const char* name : {"notes.txt", "clip", "clip.avi.sh", "photo.JPG"}) {
    const Response a = handler->handle(upload(name, "x"));
    EXPECT_EQ(a.status, 415) << name;
    EXPECT_NE(error_of(a).find("is not a file the studio opens"), std::string::npos) << error_of(a);
  }
  Request form = upload("clip.avi", "--b\r\nContent-Disposition: form-data\r\n\r\nx\r\n--b--\r\n");
  form.headers.emplace_back("Content-Type", "multipart/form-data; boundary=b");
  EXPECT_EQ(handler->handle(form).status, 415);
  EXPECT_FALSE(fs::exists(root / "uploads"));
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(StudioUploadTest, TooLargeIsRefusedDeclaredOrStreamed) {
  Handler small(root, AccessRules{kToken, kPort, 1000, 200, 400, 100}, Assets{"", ""}, backend);
  // The whole body over the limit.
  Response a = small.handle(upload("clip.avi", std::string(101, 'x')));
  EXPECT_EQ(a.status, 413);
  EXPECT_NE(error_of(a).find("'clip.avi' is longer than the studio takes (0.0 MB)"), std::string::npos) << error_of(a);
  // A declared size over the limit: refused before a byte is read.
  Request declared = upload("clip.avi", "");
  declared.headers.emplace_back("Content-Length", "5000000000");
  bool read = false;
  declared.read_body = [&](const std::function<bool(std::string_view)>&) { return read = true; };
  const Response b = small.handle(declared);
  EXPECT_EQ(b.status, 413);
  EXPECT_NE(error_of(b).find("'clip.avi' has 5000.0 MB, more than the studio takes"), std::string::npos) << error_of(b);
  EXPECT_FALSE(read);
  // Streamed without a declared size (chunked): stopped when it passes the limit.
  Request chunked = upload("clip.avi", "");
  int pieces = 0;
  chunked.read_body = [&](const std::function<bool(std::string_view)>& piece) {
    for (; pieces < 1000; ++pieces)
      if (!piece(std::string(30, 'x'))) return false;
    return true;
  };
  EXPECT_EQ(small.handle(chunked).status, 413);
  EXPECT_EQ(pieces, 3);  // 90 bytes taken, the 4th piece refused: the rest is never read
  // Exactly the limit is taken; nothing was left by the refused ones.
  EXPECT_EQ(small.handle(upload("clip.avi", std::string(100, 'x'))).status, 200);
  EXPECT_EQ(uploaded(), std::vector<std::string>{"clip.avi"});
  // A JSON body still has its own, smaller limit.
  EXPECT_EQ(small.handle(good("POST", "/api/track", std::string(1001, ' '))).status, 413);
}

TEST_F(StudioUploadTest, ACutConnectionOrAnEmptyFileSavesNothing) {
  Request cut = upload("clip.avi", "");
  cut.read_body = [](const std::function<bool(std::string_view)>& piece) {
    piece("first half");
    return false;  // the connection ended early
  };
  const Response a = handler->handle(cut);
  EXPECT_EQ(a.status, 400);
  EXPECT_NE(error_of(a).find("cut off"), std::string::npos) << error_of(a);
  EXPECT_EQ(handler->handle(upload("clip.avi", "")).status, 400);
  EXPECT_TRUE(uploaded().empty());
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(StudioUploadTest, AFullOrUnwritableDiskIsAClearError) {
  // A full disk, as write() sees it: the process may write files of at most 64 bytes.
  {
    struct rlimit before {};
    ::getrlimit(RLIMIT_FSIZE, &before);
    const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);  // write() then fails with EFBIG
    struct rlimit small = before;
    small.rlim_cur = 64;
    ::setrlimit(RLIMIT_FSIZE, &small);
    const Response a = handler->handle(upload("big.avi", std::string(1000, 'x')));
    ::setrlimit(RLIMIT_FSIZE, &before);
    ::signal(SIGXFSZ, old_handler);
    EXPECT_EQ(a.status, 507) << a.body;
    EXPECT_NE(error_of(a).find("the disk is full"), std::string::npos) << error_of(a);
    EXPECT_TRUE(uploaded().empty());  // the partial file removed
  }
  // uploads/ cannot be made a folder (a file of that name; a read-only folder is the same error).
  fs::remove_all(root / "uploads");
  std::ofstream(root / "uploads") << "a file";
  const Response b = handler->handle(upload("clip.avi", "x"));
  EXPECT_EQ(b.status, 507);
  EXPECT_NE(error_of(b).find("uploads/"), std::string::npos) << error_of(b);
  EXPECT_EQ(backend.calls, 0);
}

TEST_F(StudioUploadTest, AFileTheBackendCannotOpenIsKeptAndSaidSo) {
  struct Refusing : RecordingBackend {
    json open(const fs::path& file) override { throw InputError(file.string(), "not a video OpenCV decodes"); }
  } refusing;
  Handler h(root, AccessRules{kToken, kPort, 1000}, Assets{"", ""}, refusing);
  const Response a = h.handle(upload("fake.mp4", "not a video"));
  EXPECT_EQ(a.status, 400);
  // (the file named as in the folder, not by its absolute path)
  EXPECT_EQ(error_of(a), "uploads/fake.mp4 is saved, but the studio cannot open it: uploads/fake.mp4: not a video OpenCV decodes");
  EXPECT_EQ(uploaded(), std::vector<std::string>{"fake.mp4"});
}

TEST_F(StudioUploadTest, AnUploadWaitsForNoActionAndIsOne) {
  struct Slow : RecordingBackend {
    std::promise<void> started, release;
    json track(const TrackStart& s) override {
      started.set_value();
      release.get_future().wait();
      return {{"name", s.name}};
    }
  } slow;
  Handler h(root, AccessRules{kToken, kPort, 1000}, Assets{"", ""}, slow);
  auto tracking = std::async(std::launch::async, [&] {
    return h.handle(good("POST", "/api/track", R"({"x": 1, "y": 2, "frame": 0})"));
  });
  slow.started.get_future().wait();
  const Response a = h.handle(upload("clip.avi", "x"));
  EXPECT_EQ(a.status, 409);
  EXPECT_FALSE(fs::exists(root / "uploads"));
  slow.release.set_value();
  EXPECT_EQ(tracking.get().status, 200);
  EXPECT_EQ(h.handle(upload("clip.avi", "x")).status, 200);
  // While a file arrives, another action is refused naming the upload.
  Request slow_upload = upload("slow.avi", "");
  std::promise<void> arriving, rest;
  slow_upload.read_body = [&](const std::function<bool(std::string_view)>& piece) {
    piece("first");
    arriving.set_value();
    rest.get_future().wait();
    return piece("second");
  };
  auto sending = std::async(std::launch::async, [&] { return h.handle(slow_upload); });
  arriving.get_future().wait();
  const Response refused = h.handle(good("POST", "/api/track", R"({"x": 1, "y": 2, "frame": 0})"));
  EXPECT_EQ(refused.status, 409);
  EXPECT_NE(error_of(refused).find("(uploading a file)"), std::string::npos) << error_of(refused);
  EXPECT_EQ(h.handle(good("GET", "/api/frame?i=0")).status, 200);  // frames are still served meanwhile
  rest.set_value();
  EXPECT_EQ(sending.get().status, 200);
  EXPECT_EQ(read(root / "uploads" / "slow.avi"), "firstsecond");
}

TEST(Token, Has256RandomBits) {
  const std::string a = make_token(), b = make_token();
  EXPECT_EQ(a.size(), 64u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace tribolab::studio
