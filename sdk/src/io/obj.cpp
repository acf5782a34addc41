#include "io/obj.h"

#include "io/file.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <system_error>

namespace prox::io {
namespace {

constexpr std::size_t kMaxVertices = 0xFFFFFFFFu;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The next whitespace-separated token of [p, end); empty at the end.
std::string_view next_token(const char*& p, const char* end) {
  while (p != end && is_space(*p)) ++p;
  const char* begin = p;
  while (p != end && !is_space(*p)) ++p;
  return {begin, static_cast<std::size_t>(p - begin)};
}

// from_chars is locale-independent, but does not take a leading '+'.
const char* skip_plus(std::string_view s) {
  const char* p = s.data();
  if (s.size() > 1 && p[0] == '+' && p[1] != '-') ++p;
  return p;
}

// A token for an error message, cut short: a line may be 10^8 characters.
std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;
  if (token.size() <= kShown) return "'" + std::string(token) + "'";
  return "'" + std::string(token.substr(0, kShown)) + "...' (" + std::to_string(token.size()) +
         " characters)";
}

bool parse_double(std::string_view s, double& x) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(skip_plus(s), end, x);
  return ec == std::errc() && ptr == end;
}

bool parse_integer(std::string_view s, long long& x) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(skip_plus(s), end, x);
  return ec == std::errc() && ptr == end;
}

// A face vertex: "i", "i/j", "i//k" or "i/j/k". Only i is kept.
bool parse_face_vertex(std::string_view s, long long& index) {
  std::string_view part[3];
  int parts = 0;
  for (std::size_t begin = 0;; ++parts) {
    if (parts == 3) return false;
    const std::size_t slash = s.find('/', begin);
    part[parts] = s.substr(begin, slash == std::string_view::npos ? std::string_view::npos : slash - begin);
    if (slash == std::string_view::npos) {
      ++parts;
      break;
    }
    begin = slash + 1;
  }
  long long unused;
  if (!parse_integer(part[0], index)) return false;
  if (parts == 2 && !parse_integer(part[1], unused)) return false;
  if (parts == 3 &&
      ((!part[1].empty() && !parse_integer(part[1], unused)) || !parse_integer(part[2], unused)))
    return false;
  return true;
}

class Parser {
 public:
  Parser(const std::string& name, ObjData& out) : name_(name), out_(out) {}

  Status parse(const std::string& text) {
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p != end) {
      ++line_;
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      if (eol == nullptr) eol = end;
      const char* comment = static_cast<const char*>(std::memchr(p, '#', static_cast<std::size_t>(eol - p)));
      Status status = parse_line(p, comment != nullptr ? comment : eol);
      if (!status) return status;
      p = eol == end ? end : eol + 1;
    }
    return Status::ok();
  }

 private:
  Status error(const std::string& message) const {
    return {StatusCode::ParseError, name_ + ":" + std::to_string(line_) + ": " + message};
  }

  Status parse_line(const char* p, const char* end) {
    const std::string_view keyword = next_token(p, end);
    if (keyword == "v") return parse_vertex(p, end);
    if (keyword == "f") return parse_face(p, end);
    // Texture coordinates, normals, groups, materials, lines, points and
    // anything unknown carry nothing Proxima uses.
    return Status::ok();
  }

  // "v x y z [w]". Numbers after z (w, or the r g b of the common vertex
  // colour extension) must be well formed but are ignored.
  Status parse_vertex(const char* p, const char* end) {
    if (vertex_count_ == kMaxVertices) return error("more than 4294967295 vertices");
    double xyz[3];
    int n = 0;
    for (std::string_view token = next_token(p, end); !token.empty(); token = next_token(p, end), ++n) {
      double x;
      if (!parse_double(token, x)) return error("malformed number " + quoted(token));
      if (!std::isfinite(x)) return error("non-finite coordinate " + quoted(token));
      if (n < 3) xyz[n] = x;
    }
    if (n < 3) return error("vertex has " + std::to_string(n) + " coordinates; 3 are needed");
    out_.positions.insert(out_.positions.end(), xyz, xyz + 3);
    ++vertex_count_;
    return Status::ok();
  }

  Status parse_face(const char* p, const char* end) {
    face_.clear();
    for (std::string_view token = next_token(p, end); !token.empty(); token = next_token(p, end)) {
      long long index;
      if (!parse_face_vertex(token, index)) return error("malformed face vertex " + quoted(token));
      if (index == 0) return error("face vertex index 0 (OBJ indices start at 1)");
      // Negative indices count back from the last vertex read so far.
      const long long resolved = index > 0 ? index - 1 : static_cast<long long>(vertex_count_) + index;
      if (resolved < 0 || resolved >= static_cast<long long>(vertex_count_))
        return error("face vertex index " + std::to_string(index) +
                     " is out of range: " + std::to_string(vertex_count_) + " vertices read so far");
      face_.push_back(static_cast<std::uint32_t>(resolved));
    }
    if (face_.size() < 3)
      return error("face has " + std::to_string(face_.size()) + " vertices; at least 3 are needed");
    for (std::size_t i = 1; i + 1 < face_.size(); ++i)
      out_.indices.insert(out_.indices.end(), {face_[0], face_[i], face_[i + 1]});
    return Status::ok();
  }

  const std::string& name_;
  ObjData& out_;
  std::size_t line_ = 0;
  std::size_t vertex_count_ = 0;
  std::vector<std::uint32_t> face_;
};

}  // namespace

Status read_obj(const std::string& path, ObjData& out) {
  out = {};
  std::vector<unsigned char> bytes;
  const Status status = read_file(path, bytes);
  if (!status) return status;
  return parse_obj(std::string(bytes.begin(), bytes.end()), path, out);
}

Status parse_obj(const std::string& text, const std::string& name, ObjData& out) {
  out = {};
  Status status = Parser(name, out).parse(text);
  if (!status) out = {};
  return status;
}

}  // namespace prox::io
