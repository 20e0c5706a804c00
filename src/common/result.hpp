// The one way a fallible call returns (docs/design.md, rule 6): a value, or an error message
// complete and ready to print. std::expected is C++23; this is the part of it tumble uses.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace tumble {

struct Error {
  std::string message;
};

template <typename T>
class [[nodiscard]] Result {
 public:
  // Implicit, as std::expected's: `return value;` and `return Error{why};` both read plainly.
  Result(T value) : held_(std::in_place_index<0>, std::move(value)) {}
  Result(Error error) : held_(std::in_place_index<1>, std::move(error)) {}

  bool ok() const { return held_.index() == 0; }
  explicit operator bool() const { return ok(); }
  // Preconditions: ok() for the value, !ok() for error().
  T& value() & { return std::get<0>(held_); }
  const T& value() const& { return std::get<0>(held_); }
  T&& value() && { return std::get<0>(std::move(held_)); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const std::string& error() const { return std::get<1>(held_).message; }

 private:
  std::variant<T, Error> held_;
};

}  // namespace tumble
