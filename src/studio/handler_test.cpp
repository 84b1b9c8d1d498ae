// The security rules and error answers of the request handler, without a socket: a recording
// backend stands for the workbench, so every refusal is checked to happen before any action.
#include "studio/handler.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <future>
#include <thread>
#include <fstream>
#include <vector>
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
  json forms() override { ++calls; return json::object(); }
  json analyze(const std::string& command, const json&) override { ++calls; return {{"command", command}}; }
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
            std::move(body)};
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
  EXPECT_EQ(backend.calls, 3);
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
  EXPECT_EQ(handler->handle(good("POST", "/api/analyze", R"({"values": 3})")).status, 400);
  EXPECT_EQ(handler->handle(good("GET", "/api/frame?i=-1")).status, 400);
  EXPECT_EQ(handler->handle(good("GET", "/api/frame?i=%zz")).status, 400);
  EXPECT_EQ(backend.calls, 0);
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
  EXPECT_EQ(backend.calls, 2);
}

TEST_F(HandlerTest, MoreRequestsThanTheRateAreAnswered429) {
  // 5 a second, a burst of 5: the sixth request in a row (microseconds apart) is refused,
  // whatever it is, before any other check; a moment later requests pass again.
  Handler limited(root, AccessRules{kToken, kPort, 1000, 5, 5}, Assets{"", ""}, backend);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(limited.handle(good("GET", "/api/files")).status, 200) << i;
  const Response refused = limited.handle(good("GET", "/api/files"));
  EXPECT_EQ(refused.status, 429);
  EXPECT_NE(error_of(refused).find("too many requests"), std::string::npos);
  EXPECT_EQ(limited.handle(Request{"GET", "/api/files", {}, ""}).status, 429);  // no token either
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

TEST(Token, Has256RandomBits) {
  const std::string a = make_token(), b = make_token();
  EXPECT_EQ(a.size(), 64u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace tribolab::studio
