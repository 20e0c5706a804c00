#include "io/staged_directory.hpp"
#include "support/result_text.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

class StagedDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(::testing::TempDir()) /
            ("tumble_staged_" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  static void put(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
  static std::string get(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  int entries(const fs::path& folder) const {
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) count += entry.exists();
    return count;
  }

  fs::path root_;
};

TEST_F(StagedDirectoryTest, NothingAppearsAtTheFinalPathBeforeCommit) {
  Result<StagedDirectory> staged = StagedDirectory::create((root_ / "out/scene").string());
  ASSERT_TRUE(staged.ok()) << staged.error();
  put(fs::path(staged->path()) / "a.txt", "new");
  EXPECT_FALSE(fs::exists(root_ / "out/scene"));
  EXPECT_EQ(fs::path(staged->path()).parent_path(), root_ / "out");
  ASSERT_EQ(::tumble::testing::error_text(staged->commit()), "");
  EXPECT_EQ(get(root_ / "out/scene/a.txt"), "new");
  EXPECT_EQ(entries(root_ / "out"), 2);  // scene/ and scene/a.txt: no temporary folder left
}

TEST_F(StagedDirectoryTest, CommitReplacesAnExistingFolderWhole) {
  fs::create_directories(root_ / "scene/frames");
  put(root_ / "scene/frames/old_frame.png", "old");
  put(root_ / "scene/report.json", "old");
  Result<StagedDirectory> staged = StagedDirectory::create((root_ / "scene").string());
  ASSERT_TRUE(staged.ok()) << staged.error();
  put(fs::path(staged->path()) / "report.json", "new");
  EXPECT_EQ(get(root_ / "scene/report.json"), "old");  // untouched until commit
  ASSERT_EQ(::tumble::testing::error_text(staged->commit()), "");
  EXPECT_EQ(get(root_ / "scene/report.json"), "new");
  EXPECT_FALSE(fs::exists(root_ / "scene/frames"));
  EXPECT_EQ(entries(root_), 2);  // scene/ and its report: the old folder is gone
}

TEST_F(StagedDirectoryTest, WithoutCommitTheTemporaryFolderIsRemovedAndTheOldOneKept) {
  fs::create_directories(root_ / "scene");
  put(root_ / "scene/report.json", "old");
  {
    Result<StagedDirectory> staged = StagedDirectory::create((root_ / "scene").string());
    ASSERT_TRUE(staged.ok()) << staged.error();
    fs::create_directories(fs::path(staged->path()) / "frames");
    put(fs::path(staged->path()) / "frames/f.png", "half");
  }
  EXPECT_EQ(get(root_ / "scene/report.json"), "old");
  EXPECT_EQ(entries(root_), 2);
}

TEST_F(StagedDirectoryTest, AParentThatIsAFileIsAnError) {
  fs::create_directories(root_);
  put(root_ / "file", "x");
  Result<StagedDirectory> staged = StagedDirectory::create((root_ / "file/scene").string());
  EXPECT_FALSE(staged.ok());
  EXPECT_NE(staged.error().find("cannot create output folder " + (root_ / "file").string()),
            std::string::npos)
      << staged.error();
}

// The temporary folder is named after the final one and removed again: a final path that is no
// folder name (a NUL byte would cut it short at the file system) must never get that far.
TEST_F(StagedDirectoryTest, AFinalPathThatIsNoFolderNameIsRefused) {
  fs::create_directories(root_ / "out");
  put(root_ / "out/keep.txt", "mine");
  for (const std::string& bad :
       {(root_ / "out/").string() + std::string(1, '\0'), (root_ / "out/..").string(),
        (root_ / "out/.").string(), (root_ / "out").string() + "/"}) {
    Result<StagedDirectory> staged = StagedDirectory::create(bad);
    EXPECT_FALSE(staged.ok()) << bad;
    EXPECT_NE(staged.error().find("not a folder name"), std::string::npos) << staged.error();
  }
  EXPECT_EQ(get(root_ / "out/keep.txt"), "mine");
  EXPECT_EQ(entries(root_), 2);
}

TEST_F(StagedDirectoryTest, WithoutCommitTheParentsItCreatedAreRemovedToo) {
  fs::create_directories(root_ / "kept");
  { const auto staged = StagedDirectory::create((root_ / "kept/new/deeper/scene").string()); }
  EXPECT_TRUE(fs::exists(root_ / "kept"));
  EXPECT_EQ(entries(root_), 1);  // kept/ only
  {
    Result<StagedDirectory> staged = StagedDirectory::create((root_ / "kept/new/scene").string());
    put(root_ / "kept/new/notes.txt", "written meanwhile");  // not ours: the folder stays
  }
  EXPECT_EQ(get(root_ / "kept/new/notes.txt"), "written meanwhile");
}

}  // namespace
}  // namespace tumble::io
