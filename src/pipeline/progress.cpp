#include "pipeline/progress.hpp"

#include <unistd.h>

#include <string>

namespace tumble::pipeline {

Progress::Progress(std::int64_t total, bool quiet, std::FILE* out, const char* unit)
    : total_(total),
      quiet_(quiet),
      terminal_(::isatty(::fileno(out)) != 0),
      out_(out),
      unit_(unit),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(std::int64_t done) {
  if (quiet_ || total_ <= 0) return;
  const double elapsed = elapsed_seconds();
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  const double left = rate > 0.0 ? static_cast<double>(total_ - done) / rate : 0.0;
  if (terminal_) {
    const auto now = std::chrono::steady_clock::now();
    if (done != total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * done / total_);
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(kWidth - filled), '-');
    std::fprintf(out_, "\r[%s] %lld/%lld %s  %.1f %s/s  %d:%02d left ", bar.c_str(),
                 static_cast<long long>(done), static_cast<long long>(total_), unit_, rate, unit_,
                 static_cast<int>(left) / 60, static_cast<int>(left) % 60);
  } else {
    const int decile = static_cast<int>(10 * done / total_);
    if (decile <= last_decile_) return;
    last_decile_ = decile;
    std::fprintf(out_, "%3d%%  %lld/%lld %s  %.1f %s/s  %.0f s left\n", 10 * decile,
                 static_cast<long long>(done), static_cast<long long>(total_), unit_, rate, unit_,
                 left);
  }
  std::fflush(out_);
}

void Progress::finish() {
  if (!quiet_ && terminal_) std::fputc('\n', out_);
}

}  // namespace tumble::pipeline
