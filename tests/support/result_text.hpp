// Results as the strings tests compare: "" for a success, else the error's message.
#pragma once

#include <string>
#include <utility>

#include "common/result.hpp"

namespace tumble::testing {

inline std::string error_text(const Result<void>& result) {
  return result ? std::string() : result.error();
}

// Moves a success's value into `out` (left as it was on an error); "" or the error.
template <typename T>
std::string take(Result<T> result, T& out) {
  if (!result) return result.error();
  out = std::move(result).value();
  return {};
}

}  // namespace tumble::testing

namespace tumble::testing {

// The value, or an empty one (null, nullopt) with `error` set: for tests that check the message.
template <typename T>
T value_or_empty(Result<T> result, std::string& error) {
  if (!result) {
    error = result.error();
    return T{};
  }
  return std::move(result).value();
}

}  // namespace tumble::testing
