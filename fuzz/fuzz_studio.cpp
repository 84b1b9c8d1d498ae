// libFuzzer target: any bytes as a request to the studio's handler (src/studio/handler.hpp),
// read as "METHOD\nTARGET\nName: value\n...\n\nBODY". Every answer must be a status with a
// body; a crash, an exception escaping handle(), a sanitizer report or a hang is a bug. The
// backend only answers (the actions are tested by studio_tests and the browser test), so what
// is fuzzed is the parsing, the security rules, the routing and the checks of every JSON body,
// and the upload (POST /api/upload?name=...): its name rules, limits and the file it writes
// (into the fuzz folder's uploads/, emptied after every input).
#include "studio/handler.hpp"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace {

using nlohmann::json;
using namespace tribolab::studio;

struct AnsweringBackend : Backend {
  json files() override { return {{"files", json::array()}}; }
  json open(const std::filesystem::path& f) override { return {{"file", f.string()}}; }
  std::string frame_jpeg(int step) override { return std::to_string(step); }
  json calibrate(const CalibrationInput& c) override { return to_json(c); }
  json track(const TrackStart& s) override { return to_json(s); }
  json mark(const MarkInput& m) override { return {{"track", m.track}, {"frame", m.frame}, {"remove", m.remove}}; }
  json retrack() override { return {{"looks_pending", false}}; }
  json forms() override { return json::object(); }
  json analyze(const std::string& c, const json& v, const std::vector<std::filesystem::path>&) override { return {{"command", c}, {"values", v}}; }
  std::string report_html() override { return "<html></html>"; }
  json state() override { return json::object(); }
  json progress() override { return {{"running", false}}; }
  json cancel() override { return {{"cancelling", false}}; }
};

/// The token the fuzzer can learn from the seed inputs (fuzz/corpus/studio/).
const std::string kToken(64, '0');

const std::filesystem::path& root() {
  static const std::filesystem::path root = [] {
    auto p = std::filesystem::temp_directory_path() / "tribolab_fuzz_studio";
    std::filesystem::create_directories(p / "sub");
    return p;
  }();
  return root;
}

Handler& handler() {
  static AnsweringBackend backend;
  // No rate limit worth the name: the fuzzer sends millions of requests a second, each must be parsed.
  // Uploads of at most 64 KiB, so that one input's file is small.
  static Handler h(root(), AccessRules{kToken, 8765, 4096, 1e12, 1e12, 1 << 16}, Assets{"<html></html>", "plotly"}, backend);
  return h;
}

std::string_view line(std::string_view& rest) {
  const std::size_t n = rest.find('\n');
  const std::string_view l = rest.substr(0, n);
  rest = n == std::string_view::npos ? std::string_view{} : rest.substr(n + 1);
  return l;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  Request r;
  r.method = std::string(line(rest));
  r.target = std::string(line(rest));
  for (std::string_view l; !rest.empty() && !(l = line(rest)).empty();) {
    const std::size_t colon = l.find(": ");
    if (colon == std::string_view::npos) continue;
    r.headers.emplace_back(std::string(l.substr(0, colon)), std::string(l.substr(colon + 2)));
  }
  r.body = std::string(rest);
  const Response a = handler().handle(r);
  if (a.status < 200 || a.status > 599 || a.content_type.empty()) std::abort();
  std::error_code ec;
  std::filesystem::remove_all(root() / "uploads", ec);  // one stat when nothing was uploaded
  return 0;
}
