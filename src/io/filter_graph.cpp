#include "io/filter_graph.hpp"

extern "C" {
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/error.h>
}

namespace tumble::io::av {
namespace {

std::string failure(const std::string& call, int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return call + ": " + text;
}

// The labelled ends of a parsed description: `name` joined to pad 0 of `filter`.
AVFilterInOut* end_of(const char* name, AVFilterContext* filter, AVFilterInOut* next) {
  AVFilterInOut* end = avfilter_inout_alloc();
  if (!end) return nullptr;
  end->name = av_strdup(name);
  end->filter_ctx = filter;
  end->pad_idx = 0;
  end->next = next;
  return end;
}

}  // namespace

FilterGraph::~FilterGraph() {
  avfilter_graph_free(&graph_);
}

std::string FilterGraph::build(const std::string& description,
                               const std::vector<std::string>& sources) {
  graph_ = avfilter_graph_alloc();
  if (!graph_) return failure("avfilter_graph_alloc", AVERROR(ENOMEM));
  // One thread: libavfilter's slice threads would not change the result, but one is what the
  // rest of the writers use, and the graph's work is small beside the encoder's.
  graph_->nb_threads = 1;
  AVFilterInOut* open_outputs = nullptr;  // the sources' outputs, for the description's inputs
  for (std::size_t i = 0; i < sources.size(); ++i) {
    AVFilterContext* source = nullptr;
    const std::string name = "in" + std::to_string(i);
    const int code = avfilter_graph_create_filter(
        &source, avfilter_get_by_name("buffer"), name.c_str(), sources[i].c_str(), nullptr, graph_);
    if (code < 0) {
      avfilter_inout_free(&open_outputs);
      return failure("avfilter_graph_create_filter(buffer " + sources[i] + ")", code);
    }
    sources_.push_back(source);
    open_outputs = end_of(name.c_str(), source, open_outputs);
  }
  int code = avfilter_graph_create_filter(&sink_, avfilter_get_by_name("buffersink"), "out",
                                          nullptr, nullptr, graph_);
  if (code < 0) {
    avfilter_inout_free(&open_outputs);
    return failure("avfilter_graph_create_filter(buffersink)", code);
  }
  AVFilterInOut* open_inputs = end_of("out", sink_, nullptr);
  code =
      avfilter_graph_parse_ptr(graph_, description.c_str(), &open_inputs, &open_outputs, nullptr);
  avfilter_inout_free(&open_inputs);
  avfilter_inout_free(&open_outputs);
  if (code < 0) return failure("avfilter_graph_parse_ptr(" + description + ")", code);
  code = avfilter_graph_config(graph_, nullptr);
  if (code < 0) return failure("avfilter_graph_config(" + description + ")", code);
  return {};
}

std::string FilterGraph::push(std::size_t index, const AVFrame* frame) {
  const int code = av_buffersrc_add_frame_flags(sources_.at(index), const_cast<AVFrame*>(frame),
                                                AV_BUFFERSRC_FLAG_KEEP_REF);
  if (code < 0)
    return failure(frame ? "av_buffersrc_add_frame" : "av_buffersrc_add_frame(end)", code);
  return {};
}

int FilterGraph::pull(AVFrame* frame) {
  const int code = av_buffersink_get_frame(sink_, frame);
  if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return 0;
  return code < 0 ? code : 1;
}

}  // namespace tumble::io::av
