// A small JSON writer for the tools' machine-readable output (the CLI, the
// benchmarks): indented, NaN and infinities written as null (JSON has
// neither), numbers with 17 significant digits so they read back exactly.
// Header-only and standard C++ only: it serves the samples (which see nothing
// of the SDK but its C API) and the benchmarks alike.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace prox {

class JsonWriter {
 public:
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }
  JsonWriter& key(const std::string& k) {
    item();
    quoted(k);
    out_ += ": ";
    after_key_ = true;
    return *this;
  }
  JsonWriter& value(double v) {
    item();
    if (!std::isfinite(v)) {
      out_ += "null";
    } else {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      out_ += buf;
    }
    return *this;
  }
  JsonWriter& value(long long v) {
    item();
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& value(int v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(std::size_t v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(bool v) {
    item();
    out_ += v ? "true" : "false";
    return *this;
  }
  JsonWriter& value(const std::string& s) {
    item();
    quoted(s);
    return *this;
  }
  JsonWriter& value(const char* s) { return value(std::string(s)); }
  // Any type with x, y and z: proxVec3, glm::dvec3.
  template <typename V>
  JsonWriter& vec3(const V& v) {
    begin_array();
    inline_ = true;
    value(v.x).value(v.y).value(v.z);
    end_array();
    inline_ = false;
    return *this;
  }
  template <typename T>
  JsonWriter& field(const std::string& k, const T& v) {
    key(k);
    return value(v);
  }
  const std::string& str() const { return out_; }

 private:
  JsonWriter& open(char c) {
    item();
    out_ += c;
    ++depth_;
    first_ = true;
    return *this;
  }
  JsonWriter& close(char c) {
    --depth_;
    if (!first_ && !inline_) newline();
    out_ += c;
    first_ = false;
    return *this;
  }
  void item() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_ && depth_ > 0) out_ += inline_ ? ", " : ",";
    if (depth_ > 0 && !inline_) newline();
    first_ = false;
  }
  void newline() {
    out_ += '\n';
    out_.append(static_cast<std::size_t>(2 * depth_), ' ');
  }
  void quoted(const std::string& s) {
    out_ += '"';
    for (char c : s) {
      if (c == '"' || c == '\\') out_ += '\\';
      out_ += c;
    }
    out_ += '"';
  }
  std::string out_;
  int depth_ = 0;
  bool first_ = true, after_key_ = false, inline_ = false;
};

}  // namespace prox
