// A minimal JSON writer for the CLI's machine-readable output.
#pragma once

#include <cstdio>
#include <string>

namespace prox::cli {

class Json {
 public:
  Json& begin_object() { return open('{'); }
  Json& end_object() { return close('}'); }
  Json& begin_array() { return open('['); }
  Json& end_array() { return close(']'); }
  Json& key(const char* k) {
    comma();
    string_value(k);
    out_ += ':';
    after_key_ = true;
    return *this;
  }
  Json& value(double v) {
    comma();
    if (v != v || v == 1.0 / 0.0 || v == -1.0 / 0.0) {
      out_ += "null";  // JSON has no NaN or infinity
    } else {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      out_ += buf;
    }
    return *this;
  }
  Json& value(long long v) {
    comma();
    out_ += std::to_string(v);
    return *this;
  }
  Json& value(const char* s) {
    comma();
    string_value(s);
    return *this;
  }
  Json& value(bool b) {
    comma();
    out_ += b ? "true" : "false";
    return *this;
  }
  template <typename V>
  Json& vec3(const V& v) {
    begin_array().value(v.x).value(v.y).value(v.z);
    return end_array();
  }
  const std::string& str() const { return out_; }

 private:
  Json& open(char c) {
    comma();
    out_ += c;
    first_ = true;
    return *this;
  }
  Json& close(char c) {
    out_ += c;
    first_ = false;
    return *this;
  }
  void comma() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_ && !out_.empty()) out_ += ',';
    first_ = false;
  }
  void string_value(const char* s) {
    out_ += '"';
    for (; *s; ++s) {
      const unsigned char c = static_cast<unsigned char>(*s);
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += static_cast<char>(c);
      } else if (c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += static_cast<char>(c);
      }
    }
    out_ += '"';
  }

  std::string out_;
  bool first_ = true;
  bool after_key_ = false;
};

}  // namespace prox::cli
