#include "io/poses.h"

#include "common/quaternion.h"
#include "io/file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace prox::io {

Status parse_poses(const std::string& text, const std::string& name, std::vector<PoseRecord>& out) {
  out.clear();
  // Counted before parsing, so a file far too long is refused in one fast
  // pass and never held as poses.
  std::size_t poses = 0, line_number = 1;
  bool line_start = true;
  for (const char c : text) {
    if (c == '\n') {
      line_start = true;
      ++line_number;
    } else if (line_start && c != ' ' && c != '\t' && c != '\r') {
      line_start = false;
      if (c != '#' && ++poses > kMaxPoses)
        return Status(StatusCode::ParseError, name + ":" + std::to_string(line_number) + ": more than " +
                                                  std::to_string(kMaxPoses) + " poses; split the path");
    }
  }
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = name + ":" + std::to_string(number);
    double v[7];
    int read = 0;
    const char* at = line.c_str();
    for (; read < 7; ++read) {
      char* end = nullptr;
      v[read] = std::strtod(at, &end);
      if (end == at) break;
      at = end;
    }
    if (read != 7 || std::string(at).find_first_not_of(" \t\r\n") != std::string::npos)
      return Status(StatusCode::ParseError, where + ": expected 7 numbers: tx ty tz qw qx qy qz");
    for (double x : v)
      if (!std::isfinite(x)) return Status(StatusCode::ParseError, where + ": a number is not finite");
    if (!normalize_quaternion(v + 3))
      return Status(StatusCode::ParseError, where + ": the quaternion is zero");
    out.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
  }
  if (out.empty()) return Status(StatusCode::ParseError, name + ": no pose in the file");
  return Status();
}

Status read_poses(const std::string& path, std::vector<PoseRecord>& out) {
  std::vector<unsigned char> bytes;
  const Status s = read_file(path, bytes);
  if (!s) return s;
  return parse_poses(std::string(bytes.begin(), bytes.end()), path, out);
}

}  // namespace prox::io
