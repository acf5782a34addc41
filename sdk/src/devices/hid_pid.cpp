#include "devices/hid_pid.h"

#include <algorithm>
#include <string>

namespace prox::devices {
namespace {

constexpr std::uint32_t pid(std::uint16_t id) { return hid_usage(kPidPage, id); }
constexpr std::uint32_t kGdX = hid_usage(0x01, 0x30), kGdY = hid_usage(0x01, 0x31);
constexpr std::uint32_t kByteCount = hid_usage(0x01, 0x3B);
constexpr std::uint32_t instance(std::uint16_t n) { return hid_usage(0x0A, n); }

// PID usages (HID PID 1.0, chapter 5).
enum : std::uint16_t {
  kSetEffect = 0x21, kEffectBlockIndex = 0x22, kEffectType = 0x25, kEtConstant = 0x26,
  kDuration = 0x50, kSamplePeriod = 0x51, kGain = 0x52, kTriggerButton = 0x53, kTriggerRepeat = 0x54,
  kAxesEnable = 0x55, kDirectionEnable = 0x56, kDirection = 0x57, kSetConstantForce = 0x73,
  kMagnitude = 0x70, kEffectOperationReport = 0x77, kOpStart = 0x79, kOpStop = 0x7B, kLoopCount = 0x7C,
  kDeviceGainReport = 0x7D, kDeviceGain = 0x7E, kPoolReport = 0x7F, kRamPoolSize = 0x80,
  kSimultaneousMax = 0x83, kBlockLoadReport = 0x89, kLoadSuccess = 0x8C, kLoadFull = 0x8D, kLoadError = 0x8E,
  kBlockFreeReport = 0x90, kControlReport = 0x95, kDeviceControl = 0x96, kDcEnable = 0x97, kDcDisable = 0x98, kDcStopAll = 0x99,
  kDcReset = 0x9A, kStartDelay = 0xA7, kCreateNewEffect = 0xAB, kRamPoolAvailable = 0xAC,
};

PidSlot slot_of(const HidDescriptor& d, const HidField& f, std::uint32_t bit, std::uint32_t bits) {
  PidSlot s;
  s.present = true;
  s.report_id = f.report_id;
  s.bit = bit;
  s.bits = bits;
  s.min = f.logical_min;
  s.max = f.logical_max;
  s.report_bytes = d.report_bytes(f.kind, f.report_id);
  return s;
}

// The value of `usage` in a report of `kind` inside the logical collection
// `report` (and `inner`, when not 0): a variable field's slot, or an array
// field that lists only that usage (a number declared as an array, as
// Block Load's RAM Pool Available is; Linux keeps its raw value).
PidSlot value_of(const HidDescriptor& d, HidReportKind kind, std::uint32_t report, std::uint32_t usage,
                 std::uint32_t inner = 0) {
  for (const HidField& f : d.fields) {
    if (f.kind != kind || f.constant() || !f.in_logical(report) || (inner && !f.in_logical(inner))) continue;
    if (f.variable()) {
      for (std::uint32_t k = 0; k < f.count; ++k)
        if (f.usages[k] == usage) return slot_of(d, f, f.bit + k * f.size, f.size);
    } else if (f.usages.size() == 1 && f.usages[0] == usage) {
      return slot_of(d, f, f.bit, f.size);
    }
  }
  return {};
}

// An array field in `report` that selects among usages including `usage`,
// and the value that selects it.
PidSlot selector_of(const HidDescriptor& d, HidReportKind kind, std::uint32_t report, std::uint32_t usage,
                    std::int32_t& value) {
  for (const HidField& f : d.fields) {
    if (f.kind != kind || f.variable() || f.constant() || !f.in_logical(report)) continue;
    const auto it = std::find(f.usages.begin(), f.usages.end(), usage);
    if (it == f.usages.end() || f.usages.size() < 2) continue;
    value = f.logical_min + static_cast<std::int32_t>(it - f.usages.begin());
    return slot_of(d, f, f.bit, f.size);
  }
  return {};
}

// The value selecting `usage` in a selector field already found.
std::int32_t value_in(const HidDescriptor& d, const PidSlot& s, HidReportKind kind, std::uint32_t usage) {
  for (const HidField& f : d.fields) {
    if (f.kind != kind || f.report_id != s.report_id || f.bit != s.bit) continue;
    const auto it = std::find(f.usages.begin(), f.usages.end(), usage);
    if (it != f.usages.end()) return f.logical_min + static_cast<std::int32_t>(it - f.usages.begin());
  }
  return 0;
}

Status missing(const char* what) {
  return {StatusCode::Unsupported, std::string("HID PID device: its descriptor has no ") + what};
}

}  // namespace

Status pid_layout_of(const HidDescriptor& d, PidLayout& out) {
  out = PidLayout{};
  const bool any_pid = std::any_of(d.fields.begin(), d.fields.end(), [](const HidField& f) {
    return f.in_logical(pid(kSetEffect)) || f.in_logical(pid(kSetConstantForce));
  });
  if (!any_pid) return Status::ok();
  PidLayout p;
  const auto out_value = [&](std::uint16_t report, std::uint32_t usage, std::uint32_t inner = 0) {
    return value_of(d, HidReportKind::Output, pid(report), usage, inner);
  };
  const auto feature_value = [&](std::uint16_t report, std::uint32_t usage) {
    return value_of(d, HidReportKind::Feature, pid(report), usage);
  };

  p.effect_block = out_value(kSetEffect, pid(kEffectBlockIndex));
  p.effect_type = selector_of(d, HidReportKind::Output, pid(kSetEffect), pid(kEtConstant), p.constant_force_type);
  p.duration = out_value(kSetEffect, pid(kDuration));
  p.trigger_repeat = out_value(kSetEffect, pid(kTriggerRepeat));
  p.sample_period = out_value(kSetEffect, pid(kSamplePeriod));
  p.start_delay = out_value(kSetEffect, pid(kStartDelay));  // absent on the Arduino library
  p.gain = out_value(kSetEffect, pid(kGain));
  p.trigger_button = out_value(kSetEffect, pid(kTriggerButton));
  p.axis_enable[0] = out_value(kSetEffect, kGdX, pid(kAxesEnable));
  p.axis_enable[1] = out_value(kSetEffect, kGdY, pid(kAxesEnable));
  p.direction_enable = out_value(kSetEffect, pid(kDirectionEnable));
  p.direction[0] = out_value(kSetEffect, instance(1), pid(kDirection));
  p.direction[1] = out_value(kSetEffect, instance(2), pid(kDirection));
  p.constant_block = out_value(kSetConstantForce, pid(kEffectBlockIndex));
  p.magnitude = out_value(kSetConstantForce, pid(kMagnitude));
  p.operation_block = out_value(kEffectOperationReport, pid(kEffectBlockIndex));
  p.operation = selector_of(d, HidReportKind::Output, pid(kEffectOperationReport), pid(kOpStart), p.op_start);
  if (p.operation.present) p.op_stop = value_in(d, p.operation, HidReportKind::Output, pid(kOpStop));
  p.loop_count = out_value(kEffectOperationReport, pid(kLoopCount));
  p.device_gain = out_value(kDeviceGainReport, pid(kDeviceGain));
  p.free_block = out_value(kBlockFreeReport, pid(kEffectBlockIndex));

  // Device Control: eight one-bit variables (a bit mask) or one selector,
  // inside the PID Device Control Report collection (OpenFFBoard) or only
  // the PID Device Control one (the Arduino library).
  for (const HidField& f : d.fields) {
    if (f.kind != HidReportKind::Output || f.constant() ||
        !(f.in_logical(pid(kControlReport)) || f.in_logical(pid(kDeviceControl))))
      continue;
    if (std::find(f.usages.begin(), f.usages.end(), pid(kDcEnable)) == f.usages.end()) continue;
    const auto code = [&](std::uint16_t usage) -> std::int32_t {
      const auto it = std::find(f.usages.begin(), f.usages.end(), pid(usage));
      if (it == f.usages.end()) return 0;
      const auto k = static_cast<std::int32_t>(it - f.usages.begin());
      return f.variable() ? (1 << k) : f.logical_min + k;
    };
    p.control = slot_of(d, f, f.bit, f.variable() ? f.size * f.count : f.size);
    p.control_is_mask = f.variable();
    p.control_enable = code(kDcEnable);
    p.control_disable = code(kDcDisable);
    p.control_stop_all = code(kDcStopAll);
    p.control_reset = code(kDcReset);
    break;
  }

  std::int32_t ignored = 0;
  p.create_type = selector_of(d, HidReportKind::Feature, pid(kCreateNewEffect), pid(kEtConstant), ignored);
  p.create_byte_count = feature_value(kCreateNewEffect, kByteCount);
  p.load_block = feature_value(kBlockLoadReport, pid(kEffectBlockIndex));
  p.load_status = selector_of(d, HidReportKind::Feature, pid(kBlockLoadReport), pid(kLoadSuccess), p.load_success);
  if (p.load_status.present) {
    p.load_full = value_in(d, p.load_status, HidReportKind::Feature, pid(kLoadFull));
    p.load_error = value_in(d, p.load_status, HidReportKind::Feature, pid(kLoadError));
  }
  p.load_ram_available = feature_value(kBlockLoadReport, pid(kRamPoolAvailable));
  p.pool_ram_size = feature_value(kPoolReport, pid(kRamPoolSize));
  p.pool_max_effects = feature_value(kPoolReport, pid(kSimultaneousMax));

  // The stick's (or wheel's) position: the first input fields that are GD X
  // and Y, variable, in one report.
  for (const HidField& f : d.fields) {
    if (f.kind != HidReportKind::Input || f.constant() || !f.variable()) continue;
    for (std::size_t k = 0; k < f.usages.size() && k < f.count; ++k) {
      const int axis = f.usages[k] == kGdX ? 0 : f.usages[k] == kGdY ? 1 : -1;
      if (axis < 0 || p.position[axis].present) continue;
      if (axis == 1 && p.position[0].present && p.position[0].report_id != f.report_id) continue;
      p.position[axis] = slot_of(d, f, f.bit + std::uint32_t(k) * f.size, f.size);
    }
  }

  // What a constant force cannot do without.
  struct Need {
    const PidSlot& slot;
    const char* name;
  };
  const Need needs[] = {
      {p.effect_block, "Set Effect report's Effect Block Index"},
      {p.effect_type, "Set Effect report's Effect Type with ET Constant Force"},
      {p.duration, "Set Effect report's Duration"},
      {p.axis_enable[0], "Set Effect report's Axes Enable X"},
      {p.constant_block, "Set Constant Force report's Effect Block Index"},
      {p.magnitude, "Set Constant Force report's Magnitude"},
      {p.operation_block, "Effect Operation report's Effect Block Index"},
      {p.operation, "Effect Operation report's Op Effect Start"},
      {p.control, "PID Device Control report with DC Enable Actuators"},
      {p.create_type, "Create New Effect feature report with ET Constant Force"},
      {p.load_block, "PID Block Load feature report's Effect Block Index"},
      {p.load_status, "PID Block Load feature report's Block Load Status"},
      {p.position[0], "input report with the stick's position (Generic Desktop X)"},
  };
  for (const Need& n : needs)
    if (!n.slot.present) return missing(n.name);
  if (p.op_stop == 0) return missing("Effect Operation report's Op Effect Stop");
  p.axes = p.axis_enable[1].present ? 2 : 1;
  p.pid = true;
  out = p;
  return Status::ok();
}

}  // namespace prox::devices
