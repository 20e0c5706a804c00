// How a render is cut into chunks for a render farm: the one function that computes the frame
// ranges, used by `tumble plan` (which prints them) and `tumble render --chunk I/N` (which renders
// one), so that the two always agree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"

namespace tumble::job {

// Frames first .. end-1 of a render.
struct FrameRange {
  std::int64_t first = 0;
  std::int64_t end = 0;
  bool operator==(const FrameRange&) const = default;
};

// "A:B", as `--frames A:B` takes it and `tumble plan` prints it.
std::string range_text(const FrameRange& range);

// Frames 0 .. frame_count-1 in `chunks` consecutive ranges, in order, with no gap or overlap, as
// even as possible: the first frame_count % chunks ranges hold one frame more than the others.
// An error when there are fewer frames than chunks (a chunk of no frames) or chunks < 1.
Result<std::vector<FrameRange>> plan_chunks(std::int64_t frame_count, std::int64_t chunks);

// How many chunks of at most `frames_per_chunk` frames the render needs: ceil(frame_count /
// frames_per_chunk), then split evenly by plan_chunks (so no chunk is a short remainder).
Result<std::int64_t> chunks_of_at_most(std::int64_t frame_count, std::int64_t frames_per_chunk);

// Chunk `index` of `count` (1-based, as GNU Parallel's {#} and Slurm's array index) in
// "I/N" form, as `--chunk` takes it; nullopt when the text is not two whole numbers with
// 1 <= I <= N.
struct ChunkIndex {
  std::int64_t index = 0;  // 1 .. count
  std::int64_t count = 0;
};
std::optional<ChunkIndex> parse_chunk_index(const std::string& text);

}  // namespace tumble::job
