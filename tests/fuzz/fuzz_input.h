// Decoding a fuzzer's bytes into the values the targets need. Running out of
// bytes yields zeros, so every input is a complete program.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace prox::fuzz {

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}

  bool empty() const { return p_ == end_; }
  std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }

  std::uint8_t u8() { return p_ != end_ ? *p_++ : 0; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(u8()) << (8 * i);
    return v;
  }
  std::int32_t i32() {
    const std::uint32_t v = u32();
    std::int32_t s;
    std::memcpy(&s, &v, sizeof s);
    return s;
  }
  // Values in [0, n), n > 0.
  std::uint32_t below(std::uint32_t n) { return n <= 256 ? u8() % n : u32() % n; }
  double raw_double() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(u8()) << (8 * i);
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return d;
  }
  // A double that is often one of the values that break geometry code:
  // NaN, infinities, zero, denormals, huge and tiny; else small steps or raw
  // bits.
  double number() {
    const std::uint8_t kind = u8();
    switch (kind % 16) {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return (kind & 16) ? -std::numeric_limits<double>::infinity()
                           : std::numeric_limits<double>::infinity();
      case 2:
        return (kind & 16) ? -0.0 : 0.0;
      case 3:
        return std::numeric_limits<double>::denorm_min() * (1 + u8());
      case 4:
        return (kind & 16) ? -std::numeric_limits<double>::max() : std::numeric_limits<double>::max();
      case 5:
        return std::ldexp(1.0 + u8() / 256.0, static_cast<int>(u8()) - 128);
      case 6:
        return raw_double();
      default:
        return (static_cast<double>(i32() % 20001) / 1000.0);  // [-20, 20] in steps of 1e-3
    }
  }
  std::string bytes(std::size_t n) {
    n = n < left() ? n : left();
    std::string s(reinterpret_cast<const char*>(p_), n);
    p_ += n;
    return s;
  }
  std::string rest() { return bytes(left()); }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

// Stores any 32-bit value in a public enum field, as a C caller can; a
// static_cast to a value outside the C++ enum's range would be undefined.
template <typename E>
void set_enum(E& field, std::int32_t value) {
  static_assert(sizeof(E) == sizeof value, "public enums are 32 bits");
  std::memcpy(&field, &value, sizeof value);
}
template <typename E>
void set_enum(E& field, std::uint32_t value) {
  set_enum(field, static_cast<std::int32_t>(value));
}

}  // namespace prox::fuzz
