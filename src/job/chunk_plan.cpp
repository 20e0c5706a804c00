#include "job/chunk_plan.hpp"

#include <charconv>

namespace tumble::job {

std::string range_text(const FrameRange& range) {
  return std::to_string(range.first) + ":" + std::to_string(range.end);
}

Result<std::vector<FrameRange>> plan_chunks(std::int64_t frame_count, std::int64_t chunks) {
  if (chunks < 1) return Error{"the number of chunks must be at least 1"};
  if (chunks > frame_count) {
    return Error{std::to_string(chunks) + " chunks cannot split the scene's " +
                 std::to_string(frame_count) + " frames (a chunk would have no frame)"};
  }
  const std::int64_t size = frame_count / chunks;    // frames in every chunk
  const std::int64_t larger = frame_count % chunks;  // the first ones hold one more
  std::vector<FrameRange> ranges;
  ranges.reserve(static_cast<std::size_t>(chunks));
  std::int64_t first = 0;
  for (std::int64_t i = 0; i < chunks; ++i) {
    const std::int64_t end = first + size + (i < larger ? 1 : 0);
    ranges.push_back({first, end});
    first = end;
  }
  return ranges;
}

Result<std::int64_t> chunks_of_at_most(std::int64_t frame_count, std::int64_t frames_per_chunk) {
  if (frames_per_chunk < 1) return Error{"--chunk-frames must be at least 1"};
  return frame_count / frames_per_chunk + (frame_count % frames_per_chunk != 0 ? 1 : 0);
}

std::optional<ChunkIndex> parse_chunk_index(const std::string& text) {
  const char* const end = text.data() + text.size();
  ChunkIndex chunk;
  const auto [slash, index_error] = std::from_chars(text.data(), end, chunk.index);
  if (index_error != std::errc() || slash == end || *slash != '/') return std::nullopt;
  const auto [after, count_error] = std::from_chars(slash + 1, end, chunk.count);
  if (count_error != std::errc() || after != end) return std::nullopt;
  if (chunk.index < 1 || chunk.index > chunk.count) return std::nullopt;
  return chunk;
}

}  // namespace tumble::job
