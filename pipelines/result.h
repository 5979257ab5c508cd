// Result<T>: a value or an error message. Used at every I/O and GL boundary; the message
// names the file (or GL object) and the reason, e.g. "box.glb: accessor 3 out of range".
#pragma once
#include <optional>
#include <string>
#include <utility>

namespace mb {

template <class T>
class Result {
public:
  Result(T value) : value_(std::move(value)) {}
  static Result fail(std::string message) { Result r; r.error_ = std::move(message); return r; }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return error_; }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T take() { return std::move(*value_); }

private:
  Result() = default;
  std::optional<T> value_;
  std::string error_;
};

// Status: success or an error message.
class Status {
public:
  Status() = default;
  static Status fail(std::string message) { Status s; s.error_ = std::move(message); s.failed_ = true; return s; }
  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return error_; }

private:
  std::string error_;
  bool failed_ = false;
};

}  // namespace mb
