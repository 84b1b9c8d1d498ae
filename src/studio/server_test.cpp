// The real server on a free loopback port, spoken to over HTTP: the adapter passes method,
// target, headers and body to the handler and its answers back, and survives bytes that are
// not HTTP.
#include "studio/server.hpp"

#include <httplib.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace tribolab::studio {
namespace {

using nlohmann::json;

struct EchoBackend : Backend {
  json files() override { return {{"files", json::array({"clip.avi"})}}; }
  json open(const std::filesystem::path& f) override { return {{"file", f.filename().string()}}; }
  std::string frame_jpeg(int step) override { return std::string("\xff\xd8", 2) + std::to_string(step); }
  json calibrate(const CalibrationInput& c) override { return {{"length", c.stick_length_m}}; }
  json track(const TrackStart& s) override { return {{"name", s.name}, {"x", s.x_px}}; }
  json mark(const MarkInput& m) override { return {{"track", m.track}, {"frame", m.frame}}; }
  json retrack() override { return {{"looks_pending", false}}; }
  json forms() override { return json::object(); }
  json analyze(const std::string& c, const json&, const std::vector<std::filesystem::path>&) override { return {{"command", c}}; }
  std::string report_html() override { return "<html>report</html>"; }
  json state() override { return json::object(); }
  json progress() override { return {{"running", false}}; }
  json cancel() override { return {{"cancelling", false}}; }
};

/// Sends raw bytes to 127.0.0.1:port and returns what comes back (until the server closes).
std::string raw_exchange(int port, const std::string& bytes) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) return "connect failed";
  (void)!::write(fd, bytes.data(), bytes.size());
  ::shutdown(fd, SHUT_WR);
  std::string got;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) got.append(buf, static_cast<std::size_t>(n));
  ::close(fd);
  return got;
}

/// Sends `head` to 127.0.0.1:port, keeping the connection open as a client that has more to
/// send would, and returns the first answer (its headers and its Content-Length of body).
std::string first_answer(int port, const std::string& head) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) return "connect failed";
  timeval timeout{10, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  (void)!::write(fd, head.data(), head.size());
  std::string got;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) {
    got.append(buf, static_cast<std::size_t>(n));
    const std::size_t end = got.find("\r\n\r\n"), length = got.find("Content-Length: ");
    if (end != std::string::npos && length != std::string::npos &&
        got.size() >= end + 4 + std::stoul(got.substr(length + 16)))
      break;
  }
  ::close(fd);
  return got;
}

TEST(StudioServer, AnswersOverLoopbackAndSurvivesGarbage) {
  EchoBackend backend;
  const std::string token = make_token();
  const auto root = std::filesystem::temp_directory_path();
  Server server(0, 1000, [&](int port) {
    return std::make_unique<Handler>(root, AccessRules{token, port, 1000}, Assets{"<html></html>", "plotly"}, backend);
  });
  const int port = server.port();
  ASSERT_GT(port, 0);
  std::thread serving([&] { server.run(); });
  httplib::Client client("127.0.0.1", port);
  // cpp-httplib's client sends Host: 127.0.0.1:PORT, as a browser does.
  const httplib::Headers auth = {{"X-Tribolab-Token", token}};
  // A form (as an <input> in a <form> would post it): refused 415, its parts read and dropped
  // (the e2e test posts an empty form, whose failed parse must not change the status).
  const httplib::MultipartFormDataItems form = {{"file", std::string(1000, 'x'), "clip.avi", "video/x-msvideo"}};
  auto posted = client.Post("/api/upload?name=clip.avi", auth, form);
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->status, 415) << posted->body;
  auto files = client.Get("/api/files", auth);
  ASSERT_TRUE(files);
  EXPECT_EQ(files->status, 200);
  EXPECT_EQ(json::parse(files->body)["files"][0], "clip.avi");
  EXPECT_EQ(files->get_header_value("Cache-Control"), "no-store");
  auto frame = client.Get(("/api/frame?i=4&token=" + token).c_str());
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->get_header_value("Content-Type"), "image/jpeg");
  EXPECT_EQ(frame->body, std::string("\xff\xd8", 2) + "4");
  auto tracked = client.Post("/api/track", auth, R"({"name": "b", "x": 3.5, "y": 1, "frame": 0})", "application/json");
  ASSERT_TRUE(tracked);
  EXPECT_EQ(tracked->status, 200) << tracked->body;
  EXPECT_EQ(json::parse(tracked->body)["x"], 3.5);
  auto no_token = client.Get("/api/files");
  ASSERT_TRUE(no_token);
  EXPECT_EQ(no_token->status, 403);
  auto big = client.Post("/api/track", auth, std::string(5000, ' '), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  // Chunked (no Content-Length), which cpp-httplib's buffered handlers would read whole into
  // memory whatever its size (0.11.4 checks only a declared length): stopped at the limit.
  const std::string five_mb(5 << 20, ' ');
  auto chunked = client.Post(
      "/api/track", auth,
      [&](std::size_t offset, httplib::DataSink& sink) {
        if (offset >= five_mb.size()) {
          sink.done();
          return true;
        }
        return sink.write(five_mb.data() + offset, 64 << 10);
      },
      "application/json");
  EXPECT_TRUE(!chunked || chunked->status == 413) << chunked->status << " " << chunked->body;
  // Not HTTP at all, a broken request line, a huge header: answered or dropped, never a crash.
  (void)raw_exchange(port, std::string("\x00\x01\x02garbage\r\n\r\n", 15));
  (void)raw_exchange(port, "GET\r\n\r\n");
  (void)raw_exchange(port, "GET /api/files HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nX: " +
                               std::string(100000, 'a') + "\r\n\r\n");
  auto after = client.Get("/api/files", auth);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200);
  server.stop();
  serving.join();
}

// Uploads over the wire: the body streamed to uploads/ (raw and chunked), a refused one
// answered while the client is still sending, a declared size over the limit answered at once.
TEST(StudioServer, UploadsAreStreamedToTheFolder) {
  EchoBackend backend;
  const std::string token = make_token();
  const auto root = std::filesystem::temp_directory_path() / ("studio_server_upload_" + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);
  constexpr std::uint64_t kLimit = 256 << 20;
  Server server(0, 1000, [&](int port) {
    return std::make_unique<Handler>(root, AccessRules{token, port, 1000, 200, 400, kLimit}, Assets{"", ""}, backend);
  });
  const int port = server.port();
  std::thread serving([&] { server.run(); });
  httplib::Client client("127.0.0.1", port);
  const httplib::Headers auth = {{"X-Tribolab-Token", token}};
  const auto saved = [&](const std::string& name) {
    std::ifstream in(root / "uploads" / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  // 3 MB, far over the JSON limit of 1000 bytes, with every byte value.
  std::string video(3 << 20, '\0');
  for (std::size_t i = 0; i < video.size(); ++i) video[i] = static_cast<char>((i * 7919) >> 3);
  auto up = client.Post("/api/upload?name=my%20throw.avi", auth, video, "video/x-msvideo");
  ASSERT_TRUE(up);
  EXPECT_EQ(up->status, 200) << up->body;
  EXPECT_EQ(json::parse(up->body)["uploaded"]["file"], "uploads/my_throw.avi");
  EXPECT_EQ(json::parse(up->body)["file"], "my_throw.avi");  // the echo backend opened it
  EXPECT_TRUE(saved("my_throw.avi") == video);
  // Chunked (no Content-Length): pieces of 64 KiB as a stream would send them.
  const std::size_t total = 2 << 20;
  auto chunked = client.Post(
      "/api/upload?name=my%20throw.avi", auth,
      [&](std::size_t offset, httplib::DataSink& sink) {
        if (offset >= total) {
          sink.done();
          return true;
        }
        return sink.write(video.data() + offset, std::min<std::size_t>(64 << 10, total - offset));
      },
      "video/x-msvideo");
  ASSERT_TRUE(chunked);
  EXPECT_EQ(chunked->status, 200) << chunked->body;
  EXPECT_EQ(json::parse(chunked->body)["uploaded"]["file"], "uploads/my_throw-2.avi");
  EXPECT_TRUE(saved("my_throw-2.avi") == video.substr(0, total));
  // 160 MB, sent from a generator (the client holds none of it): the server's peak memory grows
  // by far less than the file (it is written as it arrives; the pieces are 4 KiB to 64 KiB).
  rusage before{};
  ::getrusage(RUSAGE_SELF, &before);
  const std::size_t big = 160 << 20;
  auto streamed = client.Post(
      "/api/upload?name=long.mp4", auth, big,
      [&](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
        return sink.write(video.data() + offset % (1 << 20), std::min<std::size_t>(length, 1 << 20));
      },
      "video/mp4");
  ASSERT_TRUE(streamed);
  EXPECT_EQ(streamed->status, 200) << streamed->body;
  rusage after{};
  ::getrusage(RUSAGE_SELF, &after);
  EXPECT_EQ(std::filesystem::file_size(root / "uploads" / "long.mp4"), big);
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 32 << 10) << "KiB of peak memory more after a 160 MB upload";
  std::filesystem::remove(root / "uploads" / "long.mp4");
  // A refused kind: answered (the body read and dropped), the connection usable after it.
  auto wrong = client.Post("/api/upload?name=notes.txt", auth, std::string(1 << 20, 'x'), "text/plain");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 415);
  // A form (as an <input> in a <form> would post it): refused 415, its parts read and dropped
  // (the e2e test posts an empty form, whose failed parse must not change the status).
  const httplib::MultipartFormDataItems form = {{"file", std::string(1000, 'x'), "clip.avi", "video/x-msvideo"}};
  auto posted = client.Post("/api/upload?name=clip.avi", auth, form);
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->status, 415) << posted->body;
  auto files = client.Get("/api/files", auth);
  ASSERT_TRUE(files);
  EXPECT_EQ(files->status, 200);
  EXPECT_EQ(json::parse(files->body)["upload"]["max_bytes"], kLimit);
  // More than the limit, declared: 413 before the body, which never comes.
  const std::string head = "POST /api/upload?name=big.avi HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                           "\r\nX-Tribolab-Token: " + token + "\r\nContent-Length: 10000000000\r\n\r\n";
  const std::string refused = first_answer(port, head);
  EXPECT_NE(refused.find("413"), std::string::npos) << "[" << refused.substr(0, 300) << "]";
  EXPECT_NE(refused.find("more than the studio takes"), std::string::npos) << refused.substr(0, 300);
  // Cut off: 100 of the 1000 bytes declared, then the connection closed (a tab closed, Cancel):
  // answered 400 if the client still listens, and the partial file removed.
  const std::string cut = raw_exchange(port, "POST /api/upload?name=cut.avi HTTP/1.1\r\nHost: 127.0.0.1:" +
                                                 std::to_string(port) + "\r\nX-Tribolab-Token: " + token +
                                                 "\r\nContent-Length: 1000\r\n\r\n" + std::string(100, 'x'));
  EXPECT_TRUE(cut.empty() || cut.find("cut off") != std::string::npos) << cut.substr(0, 300);
  // Without the token: refused, nothing written.
  auto anonymous = client.Post("/api/upload?name=x.avi", std::string(1000, 'x'), "video/x-msvideo");
  ASSERT_TRUE(anonymous);
  EXPECT_EQ(anonymous->status, 403);
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(root / "uploads")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"my_throw-2.avi", "my_throw.avi"}));
  server.stop();
  serving.join();
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace tribolab::studio
