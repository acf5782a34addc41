#include "devices/hid_descriptor.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace prox::devices {
namespace {

// Limits that keep a hostile descriptor from costing much: Linux's
// HID_MAX_BUFFER_SIZE is 16 KiB a report, HID_MAX_USAGES 12,288.
constexpr std::uint32_t kMaxReportBytes = 4096;
constexpr std::uint32_t kMaxUsages = 12288;
constexpr std::size_t kMaxDepth = 64;  // collections, and pushes

std::uint32_t unsigned_data(const std::uint8_t* d, int n) {
  std::uint32_t v = 0;
  for (int k = 0; k < n; ++k) v |= std::uint32_t{d[k]} << (8 * k);
  return v;
}

std::int32_t signed_data(const std::uint8_t* d, int n) {
  const std::uint32_t v = unsigned_data(d, n);
  if (n == 0) return 0;
  if (n == 4) return static_cast<std::int32_t>(v);
  const std::uint32_t sign = 1u << (8 * n - 1);
  return static_cast<std::int32_t>((v ^ sign)) - static_cast<std::int32_t>(sign);
}

struct Globals {
  std::uint32_t page = 0;
  std::int32_t logical_min = 0, logical_max = 0, physical_min = 0, physical_max = 0;
  std::int32_t unit_exponent = 0;
  std::uint32_t unit = 0, size = 0, report_id = 0, count = 0;
};

Status error_at(std::size_t offset, const std::string& what) {
  return {StatusCode::ParseError, "HID report descriptor, byte " + std::to_string(offset) + ": " + what};
}

}  // namespace

bool HidField::in_logical(std::uint32_t usage) const {
  return std::any_of(collections.begin(), collections.end(),
                     [&](const HidCollection& c) { return c.type == 2 && c.usage == usage; });
}

std::uint32_t HidDescriptor::report_bytes(HidReportKind kind, std::uint8_t id) const {
  std::uint32_t end = 0;
  bool found = false;
  for (const HidField& f : fields) {
    if (f.kind != kind || f.report_id != id) continue;
    found = true;
    end = std::max(end, f.bit + f.size * f.count);
  }
  return found ? (end + 7) / 8 : 0;
}

Status parse_hid_descriptor(const std::uint8_t* data, std::size_t size, HidDescriptor& out) {
  out = HidDescriptor{};
  HidDescriptor d;
  Globals g;
  std::vector<Globals> pushed;
  std::vector<std::uint32_t> usages;
  std::uint32_t usage_min = 0;
  bool have_min = false;
  std::vector<HidCollection> collections;
  std::map<std::pair<int, std::uint32_t>, std::uint32_t> next_bit;  // (kind, id) -> bit
  std::size_t i = 0;
  while (i < size) {
    const std::uint8_t b = data[i];
    if (b == 0xFE) {  // a long item: skipped, as every host does
      if (i + 2 >= size) return error_at(i, "truncated long item");
      i += 3 + std::size_t{data[i + 1]};
      if (i > size) return error_at(i, "truncated long item");
      continue;
    }
    const int n = (b & 3) == 3 ? 4 : (b & 3);
    const int type = (b >> 2) & 3, tag = b >> 4;
    if (i + 1 + static_cast<std::size_t>(n) > size) return error_at(i, "item runs past the end");
    const std::uint8_t* v = data + i + 1;
    if (type == 0) {  // main
      if (tag == 8 || tag == 9 || tag == 0xB) {
        const HidReportKind kind = tag == 8 ? HidReportKind::Input
                                   : tag == 9 ? HidReportKind::Output
                                              : HidReportKind::Feature;
        if (g.report_id > 255) return error_at(i, "report id " + std::to_string(g.report_id) + " over 255");
        if (g.size > 32 && g.count > 0 && (unsigned_data(v, n) & 1u) == 0)
          return error_at(i, "a " + std::to_string(g.size) + "-bit data field (at most 32 are read)");
        if (g.count > kMaxUsages) return error_at(i, "report count " + std::to_string(g.count) + " too large");
        const auto key = std::make_pair(static_cast<int>(kind), g.report_id);
        auto it = next_bit.find(key);
        const std::uint32_t start = it != next_bit.end() ? it->second : (d.numbered ? 8u : 0u);
        const std::uint64_t end = std::uint64_t{start} + std::uint64_t{g.size} * g.count;
        if (end > 8ull * kMaxReportBytes) return error_at(i, "report larger than 4096 bytes");
        HidField f;
        f.kind = kind;
        f.report_id = static_cast<std::uint8_t>(g.report_id);
        f.bit = start;
        f.size = g.size;
        f.count = g.count;
        f.flags = unsigned_data(v, n);
        f.logical_min = g.logical_min, f.logical_max = g.logical_max;
        f.physical_min = g.physical_min, f.physical_max = g.physical_max;
        f.unit = g.unit;
        f.unit_exponent = g.unit_exponent;
        f.declared_usages = static_cast<std::uint32_t>(usages.size());
        if (f.variable()) {
          f.usages.resize(g.count, 0u);
          for (std::uint32_t k = 0; k < g.count && !usages.empty(); ++k)
            f.usages[k] = usages[std::min<std::size_t>(k, usages.size() - 1)];
        } else {
          f.usages = usages;
        }
        f.collections = collections;
        next_bit[key] = static_cast<std::uint32_t>(end);
        d.fields.push_back(std::move(f));
      } else if (tag == 0xA) {  // collection
        if (collections.size() >= kMaxDepth) return error_at(i, "collections nested too deep");
        const HidCollection c{static_cast<std::uint8_t>(unsigned_data(v, n)), usages.empty() ? 0u : usages[0]};
        if (collections.empty() && c.type == 1) d.applications.push_back(c.usage);
        collections.push_back(c);
      } else if (tag == 0xC) {  // end collection
        if (collections.empty()) return error_at(i, "End Collection without a Collection");
        collections.pop_back();
      } else {
        return error_at(i, "unknown main item tag " + std::to_string(tag));
      }
      usages.clear();
      have_min = false;
    } else if (type == 1) {  // global
      switch (tag) {
        case 0: g.page = unsigned_data(v, n); break;
        case 1: g.logical_min = signed_data(v, n); break;
        case 2:
          g.logical_max = g.logical_min < 0 ? signed_data(v, n) : static_cast<std::int32_t>(unsigned_data(v, n));
          break;
        case 3: g.physical_min = signed_data(v, n); break;
        case 4:
          g.physical_max =
              g.physical_min < 0 ? signed_data(v, n) : static_cast<std::int32_t>(unsigned_data(v, n));
          break;
        case 5: {
          // One nibble, signed, as hid-core reads it (a wider value as is).
          const std::int32_t e = signed_data(v, n);
          g.unit_exponent = (e >= 0 && e <= 15) ? (e & 7) - (e & 8) : e;
          break;
        }
        case 6: g.unit = unsigned_data(v, n); break;
        case 7: g.size = unsigned_data(v, n); break;
        case 8:
          g.report_id = unsigned_data(v, n);
          if (g.report_id == 0) return error_at(i, "report id 0 (reserved)");
          d.numbered = true;
          break;
        case 9: g.count = unsigned_data(v, n); break;
        case 0xA:
          if (pushed.size() >= kMaxDepth) return error_at(i, "Push nested too deep");
          pushed.push_back(g);
          break;
        case 0xB:
          if (pushed.empty()) return error_at(i, "Pop without a Push");
          g = pushed.back();
          pushed.pop_back();
          break;
        default: break;  // reserved: ignored
      }
    } else if (type == 2 && tag <= 2) {  // usage, usage minimum, usage maximum
      const std::uint32_t value = unsigned_data(v, n);
      const std::uint32_t full = n == 4 ? value : (g.page << 16) | value;
      if (tag == 0) {
        if (usages.size() >= kMaxUsages) return error_at(i, "too many usages");
        usages.push_back(full);
      } else if (tag == 1) {
        usage_min = full;
        have_min = true;
      } else {
        if (!have_min) return error_at(i, "Usage Maximum without a Usage Minimum");
        if (full < usage_min || full - usage_min >= kMaxUsages - usages.size())
          return error_at(i, "usage range out of order or too large");
        // Counted, not `u <= full`: a range ending at 0xFFFFFFFF would wrap
        // and never end (the fuzzer's find).
        for (std::uint32_t k = 0; k <= full - usage_min; ++k) usages.push_back(usage_min + k);
        have_min = false;
      }
    }  // other local items (designators, strings, delimiters): not needed
    i += 1 + static_cast<std::size_t>(n);
  }
  if (!collections.empty())
    return error_at(size, std::to_string(collections.size()) + " collection(s) left open");
  out = std::move(d);
  return Status::ok();
}

std::int64_t read_hid_bits(const std::uint8_t* report, std::size_t size, std::uint32_t bit, std::uint32_t bits,
                           bool is_signed) {
  if (bits == 0 || bits > 32 || std::uint64_t{bit} + bits > 8ull * size) return 0;
  std::uint64_t v = 0;
  for (std::uint32_t k = 0; k < bits; ++k) {
    const std::uint32_t at = bit + k;
    v |= std::uint64_t{(report[at / 8] >> (at % 8)) & 1u} << k;
  }
  if (is_signed && (v >> (bits - 1)) & 1u) return static_cast<std::int64_t>(v) - (std::int64_t{1} << bits);
  return static_cast<std::int64_t>(v);
}

void write_hid_bits(std::uint8_t* report, std::size_t size, std::uint32_t bit, std::uint32_t bits,
                    std::int64_t value) {
  if (bits == 0 || bits > 32 || std::uint64_t{bit} + bits > 8ull * size) return;
  const auto v = static_cast<std::uint64_t>(value);
  for (std::uint32_t k = 0; k < bits; ++k) {
    const std::uint32_t at = bit + k;
    const auto mask = static_cast<std::uint8_t>(1u << (at % 8));
    if ((v >> k) & 1u)
      report[at / 8] = static_cast<std::uint8_t>(report[at / 8] | mask);
    else
      report[at / 8] = static_cast<std::uint8_t>(report[at / 8] & ~mask);
  }
}

}  // namespace prox::devices
