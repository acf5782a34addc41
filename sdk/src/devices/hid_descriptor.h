// HID report descriptors (HID 1.11, section 6.2.2), parsed into the fields
// of each report as a host reads and writes them: what a device that is
// recognised by what it declares (a force-feedback device's PID reports,
// docs/devices.md), not by a table of ids, is driven from. The item rules
// follow Linux's hid-core, which the devices are tested against: a logical
// or physical maximum is unsigned unless its minimum is negative, a
// one-nibble unit exponent is signed, a variable main item with fewer
// usages than its report count repeats the last usage, and local items are
// cleared after every main item.
#pragma once

#include "common/status.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prox::devices {

enum class HidReportKind : std::uint8_t { Input = 0, Output = 1, Feature = 2 };

// A usage as one number: its page in the high 16 bits.
constexpr std::uint32_t hid_usage(std::uint16_t page, std::uint16_t id) {
  return (std::uint32_t{page} << 16) | id;
}

struct HidCollection {
  std::uint8_t type = 0;    // 0 physical, 1 application, 2 logical, ...
  std::uint32_t usage = 0;  // its first usage, 0 when it has none
};

// One main item: `count` slots of `size` bits from `bit` on.
struct HidField {
  HidReportKind kind = HidReportKind::Input;
  std::uint8_t report_id = 0;  // 0 when the descriptor numbers no reports
  // Offset into the buffer hidapi reads and writes: byte 0 is the report id
  // when the descriptor numbers its reports.
  std::uint32_t bit = 0;
  std::uint32_t size = 0, count = 0;
  std::uint32_t flags = 0;  // the main item's: bit 0 constant, bit 1 variable, bit 2 relative, ...
  std::int32_t logical_min = 0, logical_max = 0, physical_min = 0, physical_max = 0;
  std::uint32_t unit = 0;
  std::int32_t unit_exponent = 0;
  // A variable field: one usage per slot. An array field: the usages its
  // slots select from, value logical_min + k selecting usages[k].
  std::vector<std::uint32_t> usages;
  std::uint32_t declared_usages = 0;  // as the descriptor listed them
  std::vector<HidCollection> collections;  // enclosing, outermost first

  bool constant() const { return (flags & 1u) != 0; }
  bool variable() const { return (flags & 2u) != 0; }
  // Whether a logical collection around the field has this usage.
  bool in_logical(std::uint32_t usage) const;
};

struct HidDescriptor {
  std::vector<HidField> fields;  // in descriptor order
  bool numbered = false;         // reports carry an id byte
  std::vector<std::uint32_t> applications;  // the top-level application collections' usages

  // A report's size in bytes (the id byte included when numbered); 0 when
  // the descriptor has no such report.
  std::uint32_t report_bytes(HidReportKind kind, std::uint8_t id) const;
};

// Parses `size` bytes; on error (a truncated item, an unbalanced collection
// or push, a report larger than 4096 bytes, ...) the status names the byte
// offset and `out` is empty.
Status parse_hid_descriptor(const std::uint8_t* data, std::size_t size, HidDescriptor& out);

// A little-endian bit field of `bits` (1..32) at `bit` in a report of `size`
// bytes: read sign-extended when `is_signed`, written truncated. Out of the
// report: read gives 0, write does nothing.
std::int64_t read_hid_bits(const std::uint8_t* report, std::size_t size, std::uint32_t bit, std::uint32_t bits,
                           bool is_signed);
void write_hid_bits(std::uint8_t* report, std::size_t size, std::uint32_t bit, std::uint32_t bits,
                    std::int64_t value);

}  // namespace prox::devices
