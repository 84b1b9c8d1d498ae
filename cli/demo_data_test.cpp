// The shipped demo data is exactly what its committed commands make (data/demo/README.md).
#include "cli_test_util.hpp"
#include "app/demo/demo_data.hpp"

#include <filesystem>
#include <set>

namespace tribolab::cli::testing {
namespace {

using namespace tribolab::app;  // the demo lives in the application layer

namespace fs = std::filesystem;

const fs::path kDemoData = fs::path(TRIBOLAB_SOURCE_DIR) / "data" / "demo";

TEST(DemoData, EmbeddedFilesAreTheCommittedFiles) {
  for (const DemoFile& f : demo_files()) {
    EXPECT_EQ(slurp((kDemoData / f.name).string()), f.content) << f.name;
    EXPECT_EQ(demo_file(f.name), f.content);
  }
  EXPECT_THROW(demo_file("no/such/file.txt"), std::logic_error);
}

TEST(DemoData, EveryStudyScriptReproducesItsFilesByteForByte) {
  std::set<std::string> made;
  const std::string root = temp_dir("demo_data");
  for (const auto& study : fs::directory_iterator(kDemoData)) {
    const fs::path script = study.path() / "make.sh";
    if (!study.is_directory()) continue;
    ASSERT_TRUE(fs::exists(script)) << study.path() << " has data but no make.sh";
    const std::string out = root + "/" + study.path().filename().string();
    fs::create_directories(out);
    const std::string cmd = "TRIBOLAB='" + std::string(TRIBOLAB_BINARY) + "' OUT='" + out +
                            "' sh '" + script.string() + "' >/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    for (const auto& f : fs::directory_iterator(out)) {
      const std::string name = study.path().filename().string() + "/" + f.path().filename().string();
      made.insert(name);
      EXPECT_EQ(slurp(f.path().string()), demo_file(name)) << name << " differs from what make.sh makes";
    }
  }
  for (const DemoFile& f : demo_files()) {
    EXPECT_TRUE(made.count(f.name)) << f.name << " is not made by its study's make.sh";
  }
}

TEST(DemoData, WriteDemoFileWritesTheEmbeddedBytes) {
  const auto files = demo_files();
  ASSERT_FALSE(files.empty()) << "the demo ships data (data/demo/<study>/)";
  const std::string dir = temp_dir("demo_data_write");
  const std::string path = write_demo_file(files.front().name, dir);
  EXPECT_EQ(slurp(path), files.front().content);
}

}  // namespace
}  // namespace tribolab::cli::testing
