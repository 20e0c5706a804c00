// The ranges of `tumble plan` and `render --chunk`: every frame once, in order, as even as
// possible; and the I/N form of --chunk.
#include "job/chunk_plan.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <vector>

namespace tumble::job {
namespace {

std::vector<std::string> texts(const std::vector<FrameRange>& ranges) {
  std::vector<std::string> out;
  for (const FrameRange& range : ranges) out.push_back(range_text(range));
  return out;
}

TEST(ChunkPlan, AnEvenSplitHasEqualChunks) {
  const Result<std::vector<FrameRange>> plan = plan_chunks(12, 3);
  ASSERT_TRUE(plan) << plan.error();
  EXPECT_EQ(texts(*plan), (std::vector<std::string>{"0:4", "4:8", "8:12"}));
}

TEST(ChunkPlan, TheRemainderGoesOneFrameEachToTheFirstChunks) {
  const Result<std::vector<FrameRange>> plan = plan_chunks(14, 4);
  ASSERT_TRUE(plan) << plan.error();
  EXPECT_EQ(texts(*plan), (std::vector<std::string>{"0:4", "4:8", "8:11", "11:14"}));
}

// Any count and any number of chunks up to it: consecutive, covering, sizes within one frame.
TEST(ChunkPlan, EveryPlanCoversEveryFrameOnceWithSizesWithinOneFrame) {
  for (std::int64_t count = 1; count <= 40; ++count) {
    for (std::int64_t chunks = 1; chunks <= count; ++chunks) {
      const Result<std::vector<FrameRange>> plan = plan_chunks(count, chunks);
      ASSERT_TRUE(plan) << plan.error();
      ASSERT_EQ(plan->size(), static_cast<std::size_t>(chunks));
      std::int64_t next = 0, smallest = count, largest = 0;
      for (const FrameRange& range : *plan) {
        EXPECT_EQ(range.first, next) << count << " in " << chunks;
        smallest = std::min(smallest, range.end - range.first);
        largest = std::max(largest, range.end - range.first);
        next = range.end;
      }
      EXPECT_EQ(next, count);
      EXPECT_LE(largest - smallest, 1) << count << " in " << chunks;
      EXPECT_GE(smallest, 1);
    }
  }
}

TEST(ChunkPlan, MoreChunksThanFramesIsAnError) {
  const Result<std::vector<FrameRange>> plan = plan_chunks(5, 6);
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error(),
            "6 chunks cannot split the scene's 5 frames (a chunk would have no frame)");
  EXPECT_FALSE(plan_chunks(5, 0));
}

// --chunk-frames K: as few chunks of at most K frames as cover the scene.
TEST(ChunkPlan, ChunkFramesGivesTheFewestChunksOfAtMostThatMany) {
  EXPECT_EQ(*chunks_of_at_most(100, 25), 4);
  EXPECT_EQ(*chunks_of_at_most(101, 25), 5);
  EXPECT_EQ(*chunks_of_at_most(3, 25), 1);
  EXPECT_EQ(*chunks_of_at_most(100, LLONG_MAX), 1);
  // 101 frames in 5 chunks: 21, 20, 20, 20, 20, none above 25 and no short last chunk.
  EXPECT_EQ(texts(*plan_chunks(101, *chunks_of_at_most(101, 25))),
            (std::vector<std::string>{"0:21", "21:41", "41:61", "61:81", "81:101"}));
}

TEST(ChunkPlan, ParsesIOverNFromOne) {
  const std::optional<ChunkIndex> chunk = parse_chunk_index("2/3");
  ASSERT_TRUE(chunk);
  EXPECT_EQ(chunk->index, 2);
  EXPECT_EQ(chunk->count, 3);
  for (const char* bad : {"0/3", "4/3", "2", "2/", "/3", "2/3x", "-1/3", "a/b", "1/0", ""}) {
    EXPECT_FALSE(parse_chunk_index(bad)) << bad;
  }
}

}  // namespace
}  // namespace tumble::job
