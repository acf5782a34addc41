// Status: how the engine reports an error without exceptions. The C API maps
// it to a result code and a thread-local message.
#pragma once

#include <string>
#include <utility>

namespace prox {

enum class StatusCode {
  Ok = 0,
  InvalidArgument,  // the caller's data is wrong (NaN, out-of-range index, empty mesh)
  ParseError,       // a file's content is malformed
  IoError,          // a file cannot be read
  Unsupported,      // valid input using a feature Proxima does not support
};

class Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}
  static Status ok() { return {}; }

  bool is_ok() const { return code_ == StatusCode::Ok; }
  explicit operator bool() const { return is_ok(); }
  StatusCode code() const { return code_; }
  // Names the offending input: "vertex 17 has a NaN coordinate".
  const std::string& message() const { return message_; }

 private:
  StatusCode code_ = StatusCode::Ok;
  std::string message_;
};

}  // namespace prox
