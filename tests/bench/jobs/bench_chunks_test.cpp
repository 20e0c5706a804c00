// `tumble bench pipeline --chunks N`: the whole render and each chunk of the plan, each in a
// process of its own, in one table; a chunk from frame A steps the physics there first, and the
// scratch renders are gone afterwards. (The figures themselves are speed: not checked here.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::read_file;

class BenchChunks : public tumble::testing::CommandTest {};

TEST_F(BenchChunks, TablesTheWholeRenderAndEachChunkOfThePlan) {
  const Outcome run = tumble(
      "bench pipeline --chunks 3 --frames 7 --width 64 --height 36 --msaa 1 --out " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string table = read_file(dir_ / "out/pipeline.md");
  EXPECT_EQ(run.out, table);
  for (const char* row : {"| whole | 0:7 |", "| chunk 1/3 | 0:3 |", "| chunk 2/3 | 3:5 |",
                          "| chunk 3/3 | 5:7 |", "| all 3 chunks | 0:7 |"}) {
    EXPECT_NE(table.find(row), std::string::npos) << row << " in\n" << table;
  }
  // The whole render and chunk 1 start at frame 0: no physics before their first frame.
  EXPECT_NE(table.find(" (0) |\n| chunk 2/3"), std::string::npos) << table;
  EXPECT_EQ(table.find(" (0) |\n| all"), std::string::npos) << table;  // chunk 3 steps to frame 5
  EXPECT_NE(table.find("CPU of the 3 chunks / CPU of the whole render: "), std::string::npos);
  // Only the table is left: the renders were written in a scratch folder and removed.
  int entries = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "out")) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

TEST_F(BenchChunks, RefusesMoreChunksThanFrames) {
  const Outcome run =
      tumble("bench pipeline --chunks 5 --frames 4 --width 64 --height 36 --out " + path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--chunks: 5 chunks cannot split the scene's 4 frames"), std::string::npos)
      << run.err;
}

}  // namespace
