// The messages between proxima_bench and proxima_coal_peer over a pair of
// pipes: a one-byte request code, then fixed-size little-endian fields in the
// machine's own layout (both ends are built together). Header-only and free of
// Coal and of the engine, so both executables include it.
//
//   'V'                                      -> u32 length, the version string
//   'M' u32 reps, u32 nv, u32 nt,
//       nv * 3 f64 points, nt * 3 u32 indices -> u32 id, reps * f64 build seconds
//   'C' u32 a, u32 b, f64 margin,
//       9 f64 rotation (column-major), 3 f64 translation
//                                            -> f64 seconds, u64 pairs, f64 lower bound
//
// End of input (the bench closing its end) ends the peer.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prox::bench::wire {

// False when the other end has gone (or on a read or write error).
inline bool write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n, size -= static_cast<std::size_t>(n);
  }
  return true;
}
inline bool read_all(int fd, void* data, std::size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n, size -= static_cast<std::size_t>(n);
  }
  return true;
}

template <class T>
bool put(int fd, const T& value) {
  return write_all(fd, &value, sizeof value);
}
template <class T>
bool get(int fd, T& value) {
  return read_all(fd, &value, sizeof value);
}
template <class T>
bool put_vector(int fd, const std::vector<T>& v) {
  return write_all(fd, v.data(), v.size() * sizeof(T));
}
template <class T>
bool get_vector(int fd, std::vector<T>& v, std::size_t count) {
  v.resize(count);
  return read_all(fd, v.data(), count * sizeof(T));
}

}  // namespace prox::bench::wire
