// Reading whole files, for the asset readers.
#pragma once

#include "common/status.h"

#include <string>
#include <vector>

namespace prox::io {

// Reads all of `path` into `bytes`. IoError naming the file when it cannot be
// opened or read, or is not a regular file (a directory, say).
Status read_file(const std::string& path, std::vector<unsigned char>& bytes);

}  // namespace prox::io
