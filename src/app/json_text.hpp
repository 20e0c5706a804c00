// The JSON that tumble writes (report.json, contact_bench.json) is built as text; these are its
// two kinds of value that need care, in one place.
#pragma once

#include <string>

namespace tumble::app {

// A JSON string: quotes, backslashes and control characters escaped, and bytes that are not
// UTF-8 (a file name can hold any) replaced by U+FFFD, so that the file stays valid JSON.
std::string json_string(const std::string& text);

// A number with 17 significant digits (the double read back is the one written); JSON has no
// infinity or NaN, so null stands for them (a kinetic energy past 1.8e308 J, a ratio to zero).
std::string json_number(double value);

}  // namespace tumble::app
