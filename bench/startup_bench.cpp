// The program's start (docs/benchmarks.md#startup): `tribolab --help` and `tribolab bounce
// simulate` run as a separate process each iteration, as a user, a script or a test runs them;
// and the first video decoded by a process (the codec library and OpenCV's videoio with its
// ~240 libraries opened on first use, src/video/codec.hpp). Wall time of spawn + run + exit.
// TRIBOLAB_BINARY=path runs another build's program instead (a before/after comparison).
#include "video/render.hpp"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

/// Runs `tribolab args...` with its output to /dev/null; its exit status.
int run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  static const char* const other = std::getenv("TRIBOLAB_BINARY");  // another build's, to compare
  std::string prog = other ? other : TRIBOLAB_BINARY;
  argv.push_back(prog.data());
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  int status = -1;
  if (posix_spawn(&pid, prog.c_str(), &actions, nullptr, argv.data(), environ) == 0) waitpid(pid, &status, 0);
  posix_spawn_file_actions_destroy(&actions);
  return status;
}

void BM_StartHelp(benchmark::State& state) {
  for (auto _ : state)
    if (run({"--help"}) != 0) state.SkipWithError("tribolab --help failed");
}
BENCHMARK(BM_StartHelp)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StartBounceSimulate(benchmark::State& state) {
  for (auto _ : state)
    if (run({"bounce", "simulate", "--vy", "-4", "--json"}) != 0) state.SkipWithError("bounce simulate failed");
}
BENCHMARK(BM_StartBounceSimulate)->Unit(benchmark::kMillisecond)->UseRealTime();

/// `track video` on a 10-frame 160x120 clip: the start, the codec library loaded, the clip decoded.
void BM_StartTrackVideoSmallClip(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("startup_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string clip = (dir / "clip.avi").string(), out = (dir / "t.csv").string();
  tribolab::video::RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.fps = 30;
  const tribolab::video::Scene scene = [](double t) {
    tribolab::video::ShapePose p;
    p.cx_px = 40 + 200 * t;
    p.cy_px = 60;
    p.a_px = p.b_px = 10;
    return std::vector<tribolab::video::ShapePose>{p};
  };
  tribolab::video::write_video(clip, scene, 10, o);
  for (auto _ : state)
    if (run({"track", "video", clip, "--ellipse", "ball=40,60@0", "--out", out}) != 0)
      state.SkipWithError("track video failed");
  fs::remove_all(dir);
}
BENCHMARK(BM_StartTrackVideoSmallClip)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
