// Joining MP4 (H.264) or WebM (VP9) segments of one video (each written with
// VideoSettings::segment, a render farm's chunks) into the whole by stream copy, without decoding
// or encoding again. FFmpeg stays out of this header.
#pragma once

#include <string>
#include <vector>

#include "common/result.hpp"

namespace tumble::io {

// What an MP4 or WebM holds, read from its index and packets without decoding.
struct VideoSegmentInfo {
  int width = 0, height = 0;
  int fps = 0;                // frames per second (0 unless a whole number)
  long long first_frame = 0;  // the frame number of its earliest frame (its time × fps)
  long long frames = 0;       // frames it holds: first_frame .. first_frame + frames - 1
  // Frames by which its decoding leads its presentation (B-frames: x264's first packet is decoded
  // this many frame times before it is shown; 0 for a segment too short for B-frames).
  long long reorder_delay = 0;
};
// The error names the path, for a file that cannot be read whole.
Result<VideoSegmentInfo> read_segment_info(const std::string& path);

// Writes `segments`, in their order, as one video at `path` (an MP4 for H.264 segments, a WebM
// for VP9 ones): their packets copied, each with its own presentation time, and decode times
// renumbered in one run for the whole (a segment too short for B-frames decodes with no lead, so
// its own decode times would run into the next segment's). Refuses (with a message naming the
// segment) anything but segments of one codec (H.264 or VP9), one size, one frame rate and the
// same stream headers (SPS/PPS; x264's stitchable headers do not show every encoder setting, so
// the caller checks the settings themselves), each starting at the frame after the last one's,
// the first at frame 0; and a segment whose index lists more frames than its file holds (a
// truncated copy; a WebM's index does not count frames, so the caller compares each segment's
// frames with what it should hold). Written beside `path` and renamed into place, so `path` holds
// a whole video or nothing.
Result<void> join_videos(const std::vector<std::string>& segments, const std::string& path);

}  // namespace tumble::io
