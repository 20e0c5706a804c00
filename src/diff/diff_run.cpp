#include "diff/diff_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <utility>

#include "common/bounded_queue.hpp"
#include "io/png_io.hpp"
#include "io/video_decoder.hpp"

namespace tumble::diff {
namespace {

// Two frames of videos at the same position belong together only if shown at the same time;
// half a millisecond is far below any frame interval and above timestamp rounding.
constexpr double kTimeTolerance = 0.0005;  // s

struct Job {
  std::int64_t index = 0;
  std::string name;
  DiffSide first, second;
  // A PNG against an H.264 video: what the video's quantiser may have changed (perceptual only)
  io::QuantisationAllowance allowance;
};

// The frames of one input in order: the PNGs of a folder, or the pictures of a video.
class FrameFeed {
 public:
  explicit FrameFeed(const DiffInput& input) : input_(input) {}

  Result<void> open() {
    if (input_.kind != DiffInputKind::video) return Result<void>::success();
    Result<std::unique_ptr<io::VideoDecoder>> opened = io::VideoDecoder::open(input_.path);
    if (!opened) return Error{opened.error()};
    decoder_ = std::move(opened).value();
    return Result<void>::success();
  }

  // The next frame, or a side that is not present at the end. A folder's frame is only named
  // here: a worker reads it.
  Result<DiffSide> next() {
    DiffSide side;
    if (!decoder_) {
      if (position_ >= input_.frames.size()) return side;
      side.present = true;
      side.file = input_.folder + "/" + input_.frames[position_++];
      return side;
    }
    Result<std::optional<io::DecodedFrame>> frame = decoder_->next();
    if (!frame) return Error{frame.error()};
    if (*frame) {
      side.present = true;
      side.image = std::move((*frame)->image);
      side.time = (*frame)->time;
      ++position_;
    }
    return side;
  }

  std::int64_t count() const { return static_cast<std::int64_t>(position_); }
  // How the last video frame was stored; not YUV for a folder.
  io::VideoPictureFormat picture_format() const {
    return decoder_ ? decoder_->picture_format() : io::VideoPictureFormat{};
  }
  // What the video's quantiser may have changed so far; inactive for a folder.
  io::QuantisationAllowance quantisation_allowance() const {
    return decoder_ ? decoder_->quantisation_allowance() : io::QuantisationAllowance{};
  }

 private:
  const DiffInput& input_;
  std::unique_ptr<io::VideoDecoder> decoder_;
  std::size_t position_ = 0;
};

std::string size_text(const io::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// Keeps the failing frames worst first (then earliest), at most kMaxKeptFrames: the same set in
// the same order whichever thread offers which frame first.
class WorstFrames {
 public:
  explicit WorstFrames(diff::DiffMetric metric) : metric_(metric) {}

  void offer(KeptFrame frame, const diff::FrameFigures& figures) {
    std::lock_guard lock(mutex_);
    frames_.push_back({diff::badness(figures, metric_), std::move(frame)});
    std::sort(frames_.begin(), frames_.end(), [](const Ranked& a, const Ranked& b) {
      return a.badness != b.badness ? a.badness > b.badness : a.frame.index < b.frame.index;
    });
    if (frames_.size() > kMaxKeptFrames) frames_.pop_back();
  }

  std::vector<KeptFrame> take() {
    std::vector<KeptFrame> out;
    for (Ranked& ranked : frames_) out.push_back(std::move(ranked.frame));
    return out;
  }

 private:
  struct Ranked {
    double badness;
    KeptFrame frame;
  };
  diff::DiffMetric metric_;
  std::mutex mutex_;
  std::vector<Ranked> frames_;
};

// Reads a side's PNG if it has one still to read, or gives the reader's error.
Result<void> load(DiffSide& side) {
  if (!side.present || side.file.empty()) return Result<void>::success();
  const Result<io::Image> image = io::read_png(side.file);
  if (!image) return Error{image.error()};
  side.image = io::through_picture_format(*image, side.as_video);
  return Result<void>::success();
}

std::string timing_problem(const DiffSide& first, const DiffSide& second) {
  if (!first.time || !second.time || std::abs(*first.time - *second.time) <= kTimeTolerance) {
    return {};
  }
  char text[96];
  std::snprintf(text, sizeof text, "shown at %.3f s in A and at %.3f s in B", *first.time,
                *second.time);
  return text;
}

// Judges one pair. Returns "" or a read error (which stops the whole comparison).
std::string judge(Job& job, const SequenceOptions& options, FrameOutcome& outcome,
                  WorstFrames& worst) {
  outcome.index = job.index;
  outcome.name = job.name;
  if (!job.first.present || !job.second.present) {
    outcome.problem = job.first.present ? "missing from B" : "missing from A";
    return {};
  }
  if (const Result<void> loaded = load(job.first); !loaded) return loaded.error();
  if (const Result<void> loaded = load(job.second); !loaded) return loaded.error();
  const io::Image& a = job.first.image;
  const io::Image& b = job.second.image;
  if (a.width != b.width || a.height != b.height) {
    outcome.problem = "different sizes: " + size_text(a) + " in A, " + size_text(b) + " in B";
    return {};
  }
  outcome.problem = timing_problem(job.first, job.second);
  outcome.figures = diff::compare_frame(a, b, options.criteria, job.allowance);
  outcome.match = outcome.problem.empty() && outcome.figures->match;
  if (!outcome.match && options.keep_images) {
    KeptFrame kept{job.index, std::move(job.first.image), std::move(job.second.image), {}};
    kept.difference =
        diff::difference_picture(kept.first, kept.second, options.criteria, job.allowance);
    worst.offer(std::move(kept), *outcome.figures);
  }
  return {};
}

// Runs `judge` over the jobs `produce` pushes, on `threads` workers, and collects the outcomes
// in frame order. The first read error (in frame order) wins.
template <typename Produce>
Result<SequenceDiff> run_jobs(const SequenceOptions& options, Produce produce) {
  const unsigned threads =
      options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  common::BoundedQueue<Job> jobs(2 * threads);  // enough to keep workers busy, few frames in memory
  WorstFrames worst(options.criteria.metric);
  std::mutex mutex;
  SequenceDiff diff;
  std::string first_error;  // of the lowest frame index that failed
  std::int64_t error_index = INT64_MAX;
  const auto work = [&] {
    while (std::optional<Job> job = jobs.pop()) {
      FrameOutcome outcome;
      std::string error = judge(*job, options, outcome, worst);
      std::lock_guard lock(mutex);
      if (!error.empty()) jobs.abort();  // the comparison cannot finish: stop producing
      if (!error.empty() && job->index < error_index) {
        error_index = job->index;
        first_error = std::move(error);
      }
      diff.frames.push_back(std::move(outcome));
    }
  };
  std::vector<std::thread> workers;
  for (unsigned n = 0; n < threads; ++n) workers.emplace_back(work);
  std::string produce_error = produce(jobs, diff);
  jobs.close();
  for (std::thread& worker : workers) worker.join();
  if (!produce_error.empty()) return Error{std::move(produce_error)};
  if (!first_error.empty()) return Error{std::move(first_error)};
  std::sort(diff.frames.begin(), diff.frames.end(),
            [](const FrameOutcome& a, const FrameOutcome& b) { return a.index < b.index; });
  diff.worst = worst.take();
  return diff;
}

// What was done to a folder's PNGs to compare them with a video, or "" when nothing was.
std::string adaptation_text(const char* video, const char* folder,
                            const io::VideoPictureFormat& format,
                            const io::QuantisationAllowance& allowance, diff::DiffMetric metric) {
  if (format.yuv_format < 0) return {};
  std::string text = std::string(folder) + "'s frames converted to " + io::describe(format) +
                     " and back for comparison with video " + video;
  if (metric != diff::DiffMetric::perceptual || !allowance.active()) return text;
  char quantiser[160];
  std::snprintf(quantiser, sizeof quantiser,
                "; differences within %s's H.264 quantisation not counted (coarsest QP %d: "
                "macroblock RMS up to %.3g Y' and %.3g Cb/Cr levels)",
                video, allowance.qp, allowance.luma_step / 2.0, allowance.chroma_step / 2.0);
  return text + quantiser;
}

std::string video_frame_name(std::int64_t index) {
  return "frame " + std::to_string(index);
}

// Two folders: pairs by file name, over the names either holds.
std::string produce_by_name(const DiffInput& first, const DiffInput& second,
                            const SequenceOptions& options, common::BoundedQueue<Job>& jobs,
                            SequenceDiff& diff) {
  std::set<std::string> names(first.frames.begin(), first.frames.end());
  names.insert(second.frames.begin(), second.frames.end());
  const std::set<std::string> in_first(first.frames.begin(), first.frames.end());
  const std::set<std::string> in_second(second.frames.begin(), second.frames.end());
  for (std::int64_t index = 0; const std::string& name : names) {
    if (index >= options.end_frame) break;
    Job job{index++, name, {}, {}, {}};
    job.first.present = in_first.count(name) == 1;
    job.second.present = in_second.count(name) == 1;
    if (job.index < options.first_frame) continue;
    // Within the range only: a render of frames A..B-1 holds none before A, and matches a
    // whole render over its range.
    diff.first_count += job.first.present;
    diff.second_count += job.second.present;
    if (job.first.present) job.first.file = first.folder + "/" + name;
    if (job.second.present) job.second.file = second.folder + "/" + name;
    if (!jobs.push(std::move(job))) break;
  }
  return {};
}

// Any other two inputs: frame k with frame k, until both end or the range does.
std::string produce_by_position(const DiffInput& first, const DiffInput& second,
                                const SequenceOptions& options, common::BoundedQueue<Job>& jobs,
                                SequenceDiff& diff) {
  FrameFeed first_feed(first), second_feed(second);
  if (const Result<void> opened = first_feed.open(); !opened) return opened.error();
  if (const Result<void> opened = second_feed.open(); !opened) return opened.error();
  for (std::int64_t index = 0; index < options.end_frame; ++index) {
    Result<DiffSide> first_side = first_feed.next();
    if (!first_side) return first_side.error();
    Result<DiffSide> second_side = second_feed.next();
    if (!second_side) return second_side.error();
    Job job{index, {}, std::move(first_side).value(), std::move(second_side).value(), {}};
    if (!job.first.present && !job.second.present) break;
    if (!job.first.file.empty()) {
      job.first.as_video = second_feed.picture_format();
      job.allowance = second_feed.quantisation_allowance();
    }
    if (!job.second.file.empty()) {
      job.second.as_video = first_feed.picture_format();
      job.allowance = first_feed.quantisation_allowance();
    }
    const bool folder_name = first.kind == DiffInputKind::folder && job.first.present;
    job.name = folder_name ? first.frames[static_cast<std::size_t>(index)]
               : second.kind == DiffInputKind::folder && job.second.present
                   ? second.frames[static_cast<std::size_t>(index)]
                   : video_frame_name(index);
    if (index >= options.first_frame && !jobs.push(std::move(job))) break;
  }
  diff.first_count = first_feed.count();
  diff.second_count = second_feed.count();
  const bool video_first = first.kind == DiffInputKind::video;
  if (first.kind != second.kind) {  // a folder and a video
    const FrameFeed& video = video_first ? first_feed : second_feed;
    diff.adaptation =
        adaptation_text(video_first ? "A" : "B", video_first ? "B" : "A", video.picture_format(),
                        video.quantisation_allowance(), options.criteria.metric);
  }
  return {};
}

}  // namespace

bool SequenceDiff::match() const {
  return !frames.empty() && first_count == second_count &&
         std::all_of(frames.begin(), frames.end(), [](const FrameOutcome& f) { return f.match; });
}

Result<SequenceDiff> compare_sequences(const DiffInput& first, const DiffInput& second,
                                       const SequenceOptions& options) {
  const bool by_name = first.kind == DiffInputKind::folder && second.kind == DiffInputKind::folder;
  return run_jobs(options, [&](common::BoundedQueue<Job>& jobs, SequenceDiff& diff) {
    return by_name ? produce_by_name(first, second, options, jobs, diff)
                   : produce_by_position(first, second, options, jobs, diff);
  });
}

Result<SequenceDiff> compare_pair(io::Image first, io::Image second, const std::string& name,
                                  const SequenceOptions& options) {
  SequenceOptions one = options;
  one.threads = 1;
  return run_jobs(one, [&](common::BoundedQueue<Job>& jobs, SequenceDiff& diff) {
    Job job{0, name, {}, {}, {}};
    job.first.present = job.second.present = true;
    job.first.image = std::move(first);
    job.second.image = std::move(second);
    jobs.push(std::move(job));
    diff.first_count = diff.second_count = 1;
    return std::string();
  });
}

}  // namespace tumble::diff
