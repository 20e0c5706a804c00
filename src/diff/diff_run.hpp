// Comparing two sequences of frames (folders of PNGs, videos, or one of each) frame by frame:
// the engine behind `tumble diff`, callable on its own (a render checked against goldens).
// PNGs are decoded and frames compared on several threads; the outcome is the same whatever the
// thread count.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "diff/diff_inputs.hpp"
#include "diff/image_diff.hpp"
#include "io/image.hpp"
#include "io/video_decoder.hpp"

namespace tumble::diff {

// One side of a frame pair, as the producer hands it to a worker.
struct DiffSide {
  bool present = false;
  std::string file;            // a PNG to read; empty when `image` holds the frame already
  io::Image image;             // a decoded video frame (or an image read beforehand)
  std::optional<double> time;  // presentation time (s), for video frames
  // Against a YUV video: the PNG is first shown as that video would hold it (see
  // io::through_picture_format), so that chroma 4:2:0 cannot store is no difference.
  io::VideoPictureFormat as_video;
};

struct FrameOutcome {
  std::int64_t index = 0;  // position in the comparison, from 0
  std::string name;        // the frame's file name, or "frame N" for video frames
  std::string problem;     // why it cannot be compared ("missing from B"), else ""
  std::optional<diff::FrameFigures> figures;  // when compared
  bool match = false;
};

// A failing frame kept for the report: its two images and the picture of their differences.
struct KeptFrame {
  std::int64_t index = 0;
  io::Image first, second, difference;
};

struct SequenceOptions {
  diff::FrameCriteria criteria;
  std::int64_t first_frame = 0;  // compare frames first_frame .. end_frame-1
  std::int64_t end_frame = INT64_MAX;
  bool keep_images = false;  // fill SequenceDiff::worst
  unsigned threads = 0;      // 0: one per core
};

inline constexpr std::size_t kMaxKeptFrames = 10;

struct SequenceDiff {
  std::vector<FrameOutcome> frames;  // in frame order
  std::vector<KeptFrame> worst;      // failing compared frames, worst first, at most 10
  // Frames of each input: two folders', within the range; others', up to the range's end.
  std::int64_t first_count = 0;
  std::int64_t second_count = 0;
  // How a folder's PNGs were brought to a video's terms before comparing ("B's frames converted
  // to yuv420p BT.709 limited range and back for comparison with video A; ..."), else "": every
  // output says it.
  std::string adaptation;
  bool match() const;  // every frame matched and the counts agree
};

// Compares two inputs of kind folder or video (two folders pair frames by file name; otherwise
// frame k of one with frame k of the other). Fails when an input cannot be read (exit 2).
Result<SequenceDiff> compare_sequences(const DiffInput& first, const DiffInput& second,
                                       const SequenceOptions& options);

// The same for two images already read (one frame, named `name`); sizes must agree.
Result<SequenceDiff> compare_pair(io::Image first, io::Image second, const std::string& name,
                                  const SequenceOptions& options);

}  // namespace tumble::diff
