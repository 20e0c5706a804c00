// Progress of a long run on standard error: a redrawn bar on a terminal, a plain line every 10%
// otherwise (logs, CI), nothing when quiet.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>

namespace tumble::pipeline {

class Progress {
 public:
  // `unit` names what is counted, in the plural ("frames", "steps").
  Progress(std::int64_t total, bool quiet, std::FILE* out, const char* unit = "frames");
  void update(std::int64_t done);  // call after each item
  void finish();                   // ends the bar's line
  double elapsed_seconds() const;

 private:
  std::int64_t total_;
  bool quiet_;
  bool terminal_;
  std::FILE* out_;
  const char* unit_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  int last_decile_ = 0;
};

}  // namespace tumble::pipeline
