// The OBJ reader on arbitrary text: an error names the line, a success
// gives finite positions and indices in range.
#include "check.h"
#include "io/obj.h"

#include <cmath>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  prox::io::ObjData obj;
  const prox::Status status = prox::io::parse_obj(text, "fuzz.obj", obj);
  if (!status) {
    PROX_FUZZ_CHECK(status.message().rfind("fuzz.obj:", 0) == 0, "error without file and line: %s",
                    status.message().c_str());
    PROX_FUZZ_CHECK(obj.positions.empty() && obj.indices.empty(), "data left after an error");
    return 0;
  }
  PROX_FUZZ_CHECK(obj.positions.size() % 3 == 0 && obj.indices.size() % 3 == 0, "ragged arrays");
  for (const double x : obj.positions) PROX_FUZZ_CHECK(std::isfinite(x), "non-finite coordinate %g", x);
  for (const std::uint32_t i : obj.indices)
    PROX_FUZZ_CHECK(i < obj.positions.size() / 3, "index %u past %zu vertices", i, obj.positions.size() / 3);
  return 0;
}
