#include "io/atomic_file.hpp"
#include "support/result_text.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(::testing::TempDir()) /
            ("tumble_atomic_" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  static std::string get(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // "" once `text` is the whole file, else why not.
  static std::string write(Result<AtomicFile>& file, const std::string& text) {
    if (!file) return file.error();
    if (std::fputs(text.c_str(), file->stream()) < 0) return "fputs failed";
    return ::tumble::testing::error_text(file->commit());
  }
  int entries() const {
    int count = 0;
    for (auto entry = fs::directory_iterator(root_); entry != fs::directory_iterator(); ++entry) {
      ++count;
    }
    return count;
  }

  fs::path root_;
};

TEST_F(AtomicFileTest, TheFileAppearsOnlyOnCommit) {
  Result<AtomicFile> file = AtomicFile::open((root_ / "a.csv").string());
  ASSERT_TRUE(file.ok()) << file.error();
  std::fputs("rows", file->stream());
  EXPECT_FALSE(fs::exists(root_ / "a.csv"));
  ASSERT_EQ(::tumble::testing::error_text(file->commit()), "");
  EXPECT_EQ(get(root_ / "a.csv"), "rows");
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFileTest, WithoutCommitNothingIsLeftAndTheOldFileIsKept) {
  std::ofstream(root_ / "a.csv") << "old";
  {
    Result<AtomicFile> file = AtomicFile::open((root_ / "a.csv").string());
    std::fputs("half", file->stream());
  }
  EXPECT_EQ(get(root_ / "a.csv"), "old");
  EXPECT_EQ(entries(), 1);
}

// Renaming over a link would replace the link: the file it names is replaced instead.
TEST_F(AtomicFileTest, ALinkStaysALinkAndItsFileIsReplaced) {
  fs::create_directories(root_ / "real");
  std::ofstream(root_ / "real/a.csv") << "old";
  fs::create_symlink("real/a.csv", root_ / "link.csv");
  Result<AtomicFile> file = AtomicFile::open((root_ / "link.csv").string());
  ASSERT_EQ(write(file, "new"), "");
  EXPECT_TRUE(fs::is_symlink(root_ / "link.csv"));
  EXPECT_EQ(get(root_ / "real/a.csv"), "new");
  EXPECT_EQ(entries(), 2);  // real/ and link.csv: no temporary file beside either
}

TEST_F(AtomicFileTest, ADanglingLinkComesToNameTheNewFile) {
  fs::create_symlink("real.csv", root_ / "link.csv");
  Result<AtomicFile> file = AtomicFile::open((root_ / "link.csv").string());
  ASSERT_EQ(write(file, "new"), "");
  EXPECT_TRUE(fs::is_symlink(root_ / "link.csv"));
  EXPECT_EQ(get(root_ / "real.csv"), "new");
  EXPECT_EQ(entries(), 2);
}

// Only what a path *is* decides how it is written, not how it is spelt: a new file reached
// through /proc (a magic link in the middle of the path) is still written beside and renamed.
TEST_F(AtomicFileTest, APathThroughProcIsStillReplacedWhole) {
  Result<AtomicFile> file = AtomicFile::open("/proc/self/root" + (root_ / "a.csv").string());
  ASSERT_TRUE(file.ok()) << file.error();
  std::fputs("rows", file->stream());
  std::fflush(file->stream());
  EXPECT_FALSE(fs::exists(root_ / "a.csv"));
  EXPECT_EQ(entries(), 1);  // the temporary file
  ASSERT_EQ(::tumble::testing::error_text(file->commit()), "");
  EXPECT_EQ(get(root_ / "a.csv"), "rows");
  EXPECT_EQ(entries(), 1);
}

// `--out /dev/fd/N N>>log`: the descriptor tumble was handed is written, so an append appends.
TEST_F(AtomicFileTest, ADescriptorPathWritesThroughTheDescriptor) {
  std::ofstream(root_ / "log.csv") << "earlier\n";
  const int descriptor = ::open((root_ / "log.csv").c_str(), O_WRONLY | O_APPEND);
  ASSERT_GE(descriptor, 0);
  for (const std::string spelling : {"/dev/fd/", "/proc/self/fd/"}) {
    Result<AtomicFile> file = AtomicFile::open(spelling + std::to_string(descriptor));
    EXPECT_EQ(write(file, spelling + "\n"), "");
  }
  ::close(descriptor);
  EXPECT_EQ(get(root_ / "log.csv"), "earlier\n/dev/fd/\n/proc/self/fd/\n");
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFileTest, ALoopOfLinksIsAnError) {
  fs::create_symlink("b.csv", root_ / "a.csv");
  fs::create_symlink("a.csv", root_ / "b.csv");
  Result<AtomicFile> file = AtomicFile::open((root_ / "a.csv").string());
  EXPECT_FALSE(file.ok());
  EXPECT_EQ(file.error(),
            (root_ / "a.csv").string() + ": cannot create: Too many levels of symbolic links");
  EXPECT_TRUE(fs::is_symlink(root_ / "a.csv"));
  EXPECT_EQ(entries(), 2);
}

// Exactly 40 links (the kernel's limit) still lead to a file; a loop never does.
TEST_F(AtomicFileTest, AChainOfFortyLinksIsFollowed) {
  std::string previous = "real.csv";
  for (int i = 0; i < 40; ++i) {
    const std::string name = "link" + std::to_string(i);
    fs::create_symlink(previous, root_ / name);
    previous = name;
  }
  Result<AtomicFile> file = AtomicFile::open((root_ / previous).string());
  ASSERT_EQ(write(file, "new"), "");
  EXPECT_EQ(get(root_ / "real.csv"), "new");
}

// The temporary file is always a new one: a link planted at a name it might take (someone else's
// folder, a predictable process id) is never written through.
TEST_F(AtomicFileTest, ALinkPlantedAtATemporaryNameIsNotFollowed) {
  std::ofstream(root_ / "victim.txt") << "precious";
  const std::string stem = (root_ / "out.csv").string() + ".tmp-" + std::to_string(::getpid());
  fs::create_symlink(root_ / "victim.txt", stem);
  for (int n = 0; n < 1000; ++n)
    fs::create_symlink(root_ / "victim.txt", stem + "-" + std::to_string(n));
  {
    Result<AtomicFile> file = AtomicFile::open((root_ / "out.csv").string());
    if (file.ok()) {
      std::fputs("rows", file->stream());
      static_cast<void>(file->commit());
    }
  }
  EXPECT_EQ(get(root_ / "victim.txt"), "precious");
}

// A replaced file keeps its permission bits: a private file must not become world-readable.
TEST_F(AtomicFileTest, AReplacedFileKeepsItsPermissions) {
  std::ofstream(root_ / "private.csv") << "old";
  fs::permissions(root_ / "private.csv", fs::perms::owner_read | fs::perms::owner_write);
  Result<AtomicFile> file = AtomicFile::open((root_ / "private.csv").string());
  ASSERT_EQ(write(file, "new"), "");
  EXPECT_EQ(get(root_ / "private.csv"), "new");
  EXPECT_EQ(fs::status(root_ / "private.csv").permissions(),
            fs::perms::owner_read | fs::perms::owner_write);
}

// A FIFO (like /dev/stdout on a pipe) is written through, not replaced by a regular file.
TEST_F(AtomicFileTest, AFifoIsWrittenThroughNotReplaced) {
  const fs::path fifo = root_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = get(fifo); });
  Result<AtomicFile> file = AtomicFile::open(fifo.string());
  const std::string written = write(file, "through the pipe");
  reader.join();
  EXPECT_EQ(written, "");
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(AtomicFileTest, AFolderAtThePathIsAnErrorAtOnce) {
  fs::create_directories(root_ / "taken");
  Result<AtomicFile> file = AtomicFile::open((root_ / "taken").string());
  EXPECT_FALSE(file.ok());
  EXPECT_EQ(file.error(), (root_ / "taken").string() + ": cannot create: Is a directory");
  EXPECT_TRUE(fs::is_directory(root_ / "taken"));
}

}  // namespace
}  // namespace tumble::io
