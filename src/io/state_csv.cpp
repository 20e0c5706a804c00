#include "io/state_csv.hpp"

namespace tumble::io {

bool write_state_header(std::FILE* out) {
  std::fputs("t,body", out);
  for (const std::string_view column : kStateColumns) {
    std::fprintf(out, ",%.*s", static_cast<int>(column.size()), column.data());
  }
  std::fputc('\n', out);
  return std::ferror(out) == 0;
}

bool write_state_row(std::FILE* out, double t, std::string_view body, const StateRow& values) {
  std::fprintf(out, "%.17g,%.*s", t, static_cast<int>(body.size()), body.data());
  for (const double value : values) std::fprintf(out, ",%.17g", value);
  std::fputc('\n', out);
  return std::ferror(out) == 0;
}

}  // namespace tumble::io
