// Prints how Proxima parses a HID report descriptor (sdk/src/devices/
// hid_descriptor.h), as JSON, for hid_descriptor_test.py to compare with the
// shared devices folder's own decoder, field by field.
//   proxima_hid_descriptor_dump FILE.rdesc.bin
#include "devices/hid_descriptor.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <utility>
#include <vector>

using namespace prox::devices;

namespace {

const char* kind_name(HidReportKind k) {
  return k == HidReportKind::Input ? "Input" : k == HidReportKind::Output ? "Output" : "Feature";
}

void print_list(const std::vector<std::uint32_t>& v) {
  std::printf("[");
  for (std::size_t i = 0; i < v.size(); ++i) std::printf("%s%u", i ? ", " : "", v[i]);
  std::printf("]");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: proxima_hid_descriptor_dump FILE.rdesc.bin\n");
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  HidDescriptor d;
  const prox::Status s = parse_hid_descriptor(bytes.data(), bytes.size(), d);
  if (!s) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 1;
  }
  std::printf("{\"numbered\": %s, \"applications\": ", d.numbered ? "true" : "false");
  print_list(d.applications);
  std::printf(",\n \"sizes\": {");
  std::set<std::pair<int, int>> reports;
  for (const HidField& f : d.fields) reports.insert({static_cast<int>(f.kind), f.report_id});
  bool first = true;
  for (const auto& r : reports) {
    const auto kind = static_cast<HidReportKind>(r.first);
    std::printf("%s\"%s:0x%02x\": %u", first ? "" : ", ", kind_name(kind), r.second,
                d.report_bytes(kind, static_cast<std::uint8_t>(r.second)));
    first = false;
  }
  std::printf("},\n \"fields\": [");
  for (std::size_t i = 0; i < d.fields.size(); ++i) {
    const HidField& f = d.fields[i];
    std::printf("%s\n  {\"type\": \"%s\", \"report_id\": %u, \"bit\": %u, \"size\": %u, \"count\": %u, "
                "\"flags\": %u, \"declared_usages\": %u, \"lmin\": %d, \"lmax\": %d, \"pmin\": %d, \"pmax\": %d, "
                "\"unit\": %u, \"unit_exp\": %d, \"usages\": ",
                i ? "," : "", kind_name(f.kind), f.report_id, f.bit, f.size, f.count, f.flags, f.declared_usages,
                f.logical_min, f.logical_max, f.physical_min, f.physical_max, f.unit, f.unit_exponent);
    print_list(f.usages);
    std::vector<std::uint32_t> logical;
    for (const HidCollection& c : f.collections)
      if (c.type == 2) logical.push_back(c.usage);
    std::printf(", \"logical_collections\": ");
    print_list(logical);
    std::printf("}");
  }
  std::printf("\n ]}\n");
  return 0;
}
