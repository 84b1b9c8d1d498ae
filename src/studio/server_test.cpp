// The real server on a free loopback port, spoken to over HTTP: the adapter passes method,
// target, headers and body to the handler and its answers back, and survives bytes that are
// not HTTP.
#include "studio/server.hpp"

#include <httplib.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
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
  json forms() override { return json::object(); }
  json analyze(const std::string& c, const json&) override { return {{"command", c}}; }
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

}  // namespace
}  // namespace tribolab::studio
