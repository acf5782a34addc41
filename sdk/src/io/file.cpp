#include "io/file.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace prox::io {

Status read_file(const std::string& path, std::vector<unsigned char>& bytes) {
  bytes.clear();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return {StatusCode::IoError, "cannot read '" + path + "': not a regular file"};
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr)
    return {StatusCode::IoError, "cannot open '" + path + "': " + std::generic_category().message(errno)};
  unsigned char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
    bytes.insert(bytes.end(), buffer, buffer + n);
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed)
    return {StatusCode::IoError, "cannot read '" + path + "': " +
                                     (error != 0 ? std::generic_category().message(error) : "read error")};
  return Status::ok();
}

}  // namespace prox::io
