// The video codecs load on first use only (src/video/codec.hpp): a command that reads and
// writes no video or image starts without OpenCV's videoio and imgcodecs and the ~240
// libraries they bring, and one that does loads them when it needs them.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tribolab::cli::testing {
namespace {

/// The shared objects the dynamic loader opened while `tribolab <args>` ran (LD_DEBUG=files
/// writes one "file=<name> [0];  needed by ..." or "... dynamically loaded by ..." line each).
std::string loaded_files(const std::string& args, const std::string& dir) {
  const std::string log = dir + "/ld.txt";
  const std::string cmd = std::string("LD_DEBUG=files LD_DEBUG_OUTPUT='") + log + "' '" + TRIBOLAB_BINARY + "' " +
                          args + " > '" + dir + "/out.txt' 2> '" + dir + "/err.txt' < /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << slurp(dir + "/err.txt");
  // LD_DEBUG_OUTPUT appends the process id to the name
  std::string all;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().filename().string().rfind("ld.txt.", 0) == 0) {
      all += slurp(e.path().string());
      std::filesystem::remove(e.path());
    }
  }
  return all;
}

TEST(CodecLibrary, ACommandWithoutVideoLoadsNoVideoCodecs) {
  const std::string dir = temp_dir("codec_none");
  const std::string files = loaded_files("bounce simulate --vy -4 --json", dir);
  ASSERT_NE(files.find("file=libc.so"), std::string::npos) << "LD_DEBUG wrote nothing usable:\n" << files;
  EXPECT_EQ(files.find("libtribolab_codec.so"), std::string::npos) << files;
  EXPECT_EQ(files.find("libopencv_videoio"), std::string::npos) << files;
  EXPECT_EQ(files.find("libopencv_imgcodecs"), std::string::npos) << files;
  EXPECT_EQ(files.find("libavcodec"), std::string::npos) << files;
  std::filesystem::remove_all(dir);
}

TEST(CodecLibrary, ACommandThatWritesAVideoLoadsThemAndTheVideoDecodes) {
  const std::string dir = temp_dir("codec_render");
  const std::string files = loaded_files(
      "bounce render --size 160x120 --fps 100 --height 0.3 --after 0.05 --json --out " + q(dir + "/v.avi"), dir);
  EXPECT_NE(files.find("libtribolab_codec.so"), std::string::npos) << files;
  EXPECT_NE(files.find("libopencv_videoio"), std::string::npos) << files;
  // and the program reads back what it wrote: every frame, the ball never lost
  const auto render = nlohmann::json::parse(slurp(dir + "/out.txt"));
  const nlohmann::json j = run_json("track video " + q(dir + "/v.avi") + " " +
                                    render["track_video_options"].get<std::string>() + " --out " + q(dir + "/t.csv"));
  EXPECT_EQ(j["frames"], render["frames"]) << j.dump();
  EXPECT_EQ(j["tracks"]["ball"]["lost"], 0) << j.dump();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli::testing
