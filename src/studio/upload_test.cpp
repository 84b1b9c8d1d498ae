// The safe name an upload is saved under and the file written as it arrives (upload.hpp):
// nothing outside uploads/, no hidden or control characters, never over an existing file.
#include "studio/upload.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace tribolab::studio {
namespace {

namespace fs = std::filesystem;

int status_of(std::string_view given) {
  try {
    (void)upload_name(given);
  } catch (const UploadError& e) {
    return e.status;
  }
  return 200;
}

TEST(StudioUploadName, KeepsAPlainName) {
  EXPECT_EQ(upload_name("throw.avi"), "throw.avi");
  EXPECT_EQ(upload_name("VID_2026-03-01(2).MP4"), "VID_2026-03-01(2).MP4");  // the extension in any case
  EXPECT_EQ(upload_name("Würfel über Rampe.mov"), "Würfel_über_Rampe.mov");    // letters of any script kept
  EXPECT_EQ(upload_name("BallToss.trz"), "BallToss.trz");
}

TEST(StudioUploadName, DropsEveryPathPart) {
  EXPECT_EQ(upload_name("../../etc/clip.mp4"), "clip.mp4");
  EXPECT_EQ(upload_name("/abs/olute/clip.mp4"), "clip.mp4");
  EXPECT_EQ(upload_name("C:\\Users\\me\\..\\clip.mp4"), "clip.mp4");  // a Windows browser's path
  EXPECT_EQ(upload_name("..\\..\\clip.mp4"), "clip.mp4");
  EXPECT_EQ(upload_name("...mp4"), "upload.mp4");  // dots only before the extension
  EXPECT_EQ(upload_name(".mp4"), "upload.mp4");
  EXPECT_EQ(upload_name("clip.avi."), "clip.avi");  // a trailing dot dropped, as Windows does
  // ".." alone, "." or a trailing slash leave no file name of a kind the studio opens.
  for (const char* given : {"..", ".", "../", "uploads/", "a/.."}) EXPECT_EQ(status_of(given), 415) << given;
}

TEST(StudioUploadName, NoHiddenControlOrSpecialCharacters) {
  EXPECT_EQ(upload_name(".hidden.avi"), "hidden.avi");
  EXPECT_EQ(upload_name("-rf.avi"), "rf.avi");  // never read as an option
  EXPECT_EQ(upload_name("a\x01" "b\nc\td.avi"), "a_b_c_d.avi");
  EXPECT_EQ(upload_name("a  *?<>|\":b.avi"), "a_b.avi");
  EXPECT_EQ(upload_name(std::string("a\0b.avi", 7)), "a_b.avi");
  EXPECT_EQ(upload_name("bad\xff\xfeutf8.avi"), "bad_utf8.avi");
  EXPECT_EQ(upload_name("zero\u200bwidth.avi"), "zero_width.avi");
  // U+202E (right-to-left override) would show "clip\u202Eiva.exe" as "clipexe.avi": refused as an .exe.
  EXPECT_EQ(status_of("clip\u202Eiva.exe"), 415);
  EXPECT_EQ(upload_name("clip\u202Eavi.avi"), "clip_avi.avi");
  const std::string long_name = upload_name(std::string(300, 'x') + ".mp4");
  EXPECT_EQ(long_name, std::string(100, 'x') + ".mp4");
  const std::string long_utf8 = upload_name(std::string(99, 'x') + "üüü.mp4");  // cut between characters
  EXPECT_EQ(long_utf8, std::string(99, 'x') + ".mp4");
}

TEST(StudioUploadName, OnlyFilesTheStudioOpens) {
  EXPECT_EQ(status_of(""), 400);
  for (const char* given : {"notes.txt", "clip", "clip.avi.exe", "photo.jpg", "trk", ".."})
    EXPECT_EQ(status_of(given), 415) << given;
  for (const auto& ext : openable_extensions()) EXPECT_EQ(status_of("a" + ext), 200) << ext;
}

class StudioUploadFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() / ("studio_upload_test_" + std::to_string(::getpid()));
    fs::create_directories(root);
    root = fs::canonical(root);
  }
  void TearDown() override { fs::remove_all(root); }
  std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::vector<std::string> listing() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(root / "uploads")) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path root;
};

TEST_F(StudioUploadFileTest, WritesPiecesAndNeverReplacesAFile) {
  fs::create_directories(root / "uploads");
  std::ofstream(root / "uploads" / "clip.avi") << "first";
  std::ofstream(root / "uploads" / "clip-3.avi.studio.json") << "{}";  // an autosave left from a deleted clip-3.avi
  for (const std::string expected : {"uploads/clip-2.avi", "uploads/clip-4.avi"}) {
    UploadFile f(root);
    f.write("ab");
    f.write("cd");
    EXPECT_EQ(f.size(), 4u);
    EXPECT_EQ(f.commit("clip.avi"), expected);
    EXPECT_EQ(read(root / expected), "abcd");
  }
  EXPECT_EQ(read(root / "uploads" / "clip.avi"), "first");
  EXPECT_EQ(listing(), (std::vector<std::string>{"clip-2.avi", "clip-3.avi.studio.json", "clip-4.avi", "clip.avi"}));
}

TEST_F(StudioUploadFileTest, AnUncommittedUploadLeavesNothing) {
  {
    UploadFile f(root);
    f.write("partial");
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(StudioUploadFileTest, AnUploadsFolderThatIsNotAFolderIsAClearError) {
  std::ofstream(root / "uploads") << "a file";
  try {
    UploadFile f(root);
    FAIL() << "no error";
  } catch (const UploadError& e) {
    EXPECT_EQ(e.status, 507);
    EXPECT_NE(std::string(e.what()).find("uploads/ cannot be opened as a folder"), std::string::npos) << e.what();
  }
  fs::remove(root / "uploads");
  fs::create_directory_symlink(fs::temp_directory_path(), root / "uploads");  // out of the folder: not written through
  EXPECT_THROW(UploadFile f(root), UploadError);
}

}  // namespace
}  // namespace tribolab::studio
