// The one way a fallible call returns (docs/design.md, rule 6): a value, or an error message
// complete and ready to print; Result<void> when there is no value. std::expected is C++23; this is
// the part of it tumble uses. Both are [[nodiscard]]: an ignored error does not compile under
// -Werror (tests/common/nodiscard checks it).
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

// Success without a value, or an Error. `return {};` (or Result<void>::success()) succeeds and
// `return Error{why};` fails.
template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)), failed_(true) {}
  static Result success() { return {}; }

  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  // Precondition: !ok().
  const std::string& error() const { return error_.message; }

 private:
  Error error_;
  bool failed_ = false;
};

}  // namespace tumble
