// printf-style formatting into a std::string of whatever length the text needs.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

namespace tumble {

std::string printed(const char* format, auto... values) {
  const int size = std::snprintf(nullptr, 0, format, values...);
  std::string text(static_cast<std::size_t>(std::max(size, 0)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, values...);
  return text;
}

}  // namespace tumble
