// The pose-file reader on arbitrary text: an error names the file, a success
// gives finite positions and unit quaternions.
#include "check.h"
#include "io/poses.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<prox::io::PoseRecord> poses;
  const prox::Status status = prox::io::parse_poses(text, "fuzz.poses", poses);
  if (!status) {
    PROX_FUZZ_CHECK(status.message().rfind("fuzz.poses", 0) == 0, "error without the file: %s",
                    status.message().c_str());
    return 0;
  }
  PROX_FUZZ_CHECK(!poses.empty(), "success without a pose");
  for (const auto& pose : poses) {
    double n = 0;
    for (const double q : pose.rotation) n += q * q;
    for (const double x : pose.position) PROX_FUZZ_CHECK(std::isfinite(x), "non-finite position %g", x);
    PROX_FUZZ_CHECK(std::abs(n - 1.0) < 1e-9, "quaternion of squared norm %.17g", n);
  }
  return 0;
}
