// A libavfilter graph with buffer sources in and one buffer sink out, for the GIF writer's
// palette (palettegen, then paletteuse). Internal to io: it includes FFmpeg's headers.
#pragma once

#include <string>
#include <vector>

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavutil/frame.h>
}

namespace tumble::io::av {

class FilterGraph {
 public:
  FilterGraph() = default;
  ~FilterGraph();
  FilterGraph(const FilterGraph&) = delete;
  FilterGraph& operator=(const FilterGraph&) = delete;

  // Builds `description` (libavfilter's syntax, its inputs labelled [in0], [in1], … and its
  // output [out]) with a buffer source per entry of `sources` (each its "video_size=WxH:
  // pix_fmt=…:time_base=…" arguments), one thread. Returns "" or the failing call.
  std::string build(const std::string& description, const std::vector<std::string>& sources);

  // Hands a frame to source `index` (a reference is taken; the caller keeps its frame), or the
  // end of that source's stream when `frame` is null. Returns "" or the failing call.
  std::string push(std::size_t index, const AVFrame* frame);

  // The next frame out, into `frame`: 1 if there was one, 0 if the graph needs more input or has
  // ended, or a negative AVERROR.
  int pull(AVFrame* frame);

 private:
  AVFilterGraph* graph_ = nullptr;
  std::vector<AVFilterContext*> sources_;
  AVFilterContext* sink_ = nullptr;
};

}  // namespace tumble::io::av
