// Output files: atomic replacement, checks before writing, no input overwritten.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "base/input_files.h"
#include "base/output_file.h"

namespace objektiv {
namespace {

namespace fs = std::filesystem;

// A fresh, empty directory for one test.
fs::path TestDir(const char* name) {
  fs::path dir = fs::temp_directory_path() / fmt::format("objektiv-output-{}-{}", name, getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string Contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void Put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

size_t EntriesIn(const fs::path& dir) { return size_t(std::distance(fs::directory_iterator(dir), {})); }

TEST(OutputFiles, ReplaceAtomicallyAndLeaveNoTemporary) {
  fs::path dir = TestDir("replace");
  Put(dir / "a.txt", "old");
  chmod((dir / "a.txt").c_str(), 0640);
  WriteTextFileAtomically((dir / "a.txt").string(), "new contents");
  EXPECT_EQ(Contents(dir / "a.txt"), "new contents");
  EXPECT_EQ(EntriesIn(dir), 1u);
  EXPECT_EQ(fs::status(dir / "a.txt").permissions(), fs::perms(0640));  // the replaced file's mode is kept
  fs::remove_all(dir);
}

TEST(OutputFiles, FailedWriteKeepsTheOldFile) {
  fs::path dir = TestDir("failed");
  Put(dir / "a.txt", "old");
  EXPECT_THROW(WriteFileAtomically((dir / "a.txt").string(),
                                   [](const std::string& temp) {
                                     Put(temp, "half");
                                     throw InputError("disk full");
                                   }),
               InputError);
  EXPECT_EQ(Contents(dir / "a.txt"), "old");
  EXPECT_EQ(EntriesIn(dir), 1u);
  fs::remove_all(dir);
}

TEST(OutputFiles, SymlinkIsWrittenWhereItPoints) {
  fs::path dir = TestDir("symlink");
  fs::create_directory(dir / "real");
  Put(dir / "real" / "a.txt", "old");
  fs::create_symlink(dir / "real" / "a.txt", dir / "link.txt");
  WriteTextFileAtomically((dir / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(Contents(dir / "real" / "a.txt"), "new");
  fs::remove_all(dir);
}

TEST(OutputFiles, InputFilesAreNeverReplaced) {
  fs::path dir = TestDir("inputs");
  fs::create_directory(dir / "sub");
  Put(dir / "texture.png", "pixels");
  RecordInputFile((dir / "sub" / ".." / "texture.png").string());
  fs::create_symlink(dir / "texture.png", dir / "link.png");
  fs::create_hard_link(dir / "texture.png", dir / "hard.png");
  // The same file by another spelling, through a symlink, through a hard link.
  for (const fs::path& p : {dir / "texture.png", dir / "." / "texture.png", dir / "link.png", dir / "hard.png"}) {
    EXPECT_TRUE(InputFileAt(p.string())) << p;
    EXPECT_THROW(CheckOutputFile(p.string()), InputError) << p;
    EXPECT_THROW(WriteTextFileAtomically(p.string(), "overwritten"), InputError) << p;
  }
  EXPECT_EQ(Contents(dir / "texture.png"), "pixels");
  EXPECT_FALSE(InputFileAt((dir / "other.png").string()));
  try {
    CheckOutputFile((dir / "link.png").string());
  } catch (const InputError& e) {  // the message names both files
    EXPECT_NE(std::string(e.what()).find("link.png: refusing to overwrite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("texture.png"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(OutputFiles, CheckFindsUnwritableTargets) {
  fs::path dir = TestDir("check");
  Put(dir / "file", "x");
  fs::create_directory(dir / "adir");
  EXPECT_NO_THROW(CheckOutputFile((dir / "new.exr").string()));
  EXPECT_EQ(EntriesIn(dir), 2u);  // the probe leaves nothing behind
  EXPECT_THROW(CheckOutputFile((dir / "missing" / "x.exr").string()), InputError);  // directories are not created
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_THROW(CheckOutputFile((dir / "file" / "x.exr").string()), InputError);
  EXPECT_THROW(CheckOutputFile((dir / "adir").string()), InputError);
  if (geteuid() != 0) {  // root may write anywhere
    chmod((dir / "file").c_str(), 0444);
    EXPECT_THROW(CheckOutputFile((dir / "file").string()), InputError);
    EXPECT_THROW(WriteTextFileAtomically((dir / "file").string(), "y"), InputError);
    chmod((dir / "adir").c_str(), 0555);
    EXPECT_THROW(CheckOutputFile((dir / "adir" / "x.exr").string()), InputError);
    chmod((dir / "adir").c_str(), 0755);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace objektiv
