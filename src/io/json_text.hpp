// The JSON that tumble writes (report.json, contact_bench.json) is built as text; these are its
// two kinds of value that need care, in one place.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

namespace tumble::io {

// A JSON string: quotes, backslashes and control characters escaped, and bytes that are not
// UTF-8 (a file name can hold any) replaced by U+FFFD, so that the file stays valid JSON.
std::string json_string(const std::string& text);

// A number with 17 significant digits (the double read back is the one written); JSON has no
// infinity or NaN, so null stands for them (a kinetic energy past 1.8e308 J, a ratio to zero).
std::string json_number(double value);

// A JSON array of integers (as they are) or doubles (json_number), ", " between them.
template <typename Value>
std::string json_array(const std::vector<Value>& values) {
  std::string text = "[";
  for (std::size_t n = 0; n < values.size(); ++n) {
    if (n) text += ", ";
    if constexpr (std::is_integral_v<Value>) {
      text += std::to_string(values[n]);
    } else {
      text += json_number(values[n]);
    }
  }
  return text + "]";
}

}  // namespace tumble::io
