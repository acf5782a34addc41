#include "hid/emulated_pid.h"

#include "devices/hid_descriptor.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace prox::test {
namespace {

double steady_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void put(Bytes& r, const devices::PidSlot& s, std::int64_t v) {
  if (s.present) devices::write_hid_bits(r.data(), r.size(), s.bit, s.bits, v);
}

}  // namespace

std::shared_ptr<EmulatedPid> EmulatedPid::attach(EmulatedHidSpec& spec, int slots) {
  auto model = std::make_shared<EmulatedPid>();
  devices::HidDescriptor d;
  const Status parsed = devices::parse_hid_descriptor(spec.descriptor.data(), spec.descriptor.size(), d);
  EXPECT_TRUE(parsed) << parsed.message();
  const Status laid = devices::pid_layout_of(d, model->layout_);
  EXPECT_TRUE(laid && model->layout_.pid) << laid.message();
  model->effects_.resize(std::size_t(slots));
  // The bus keeps the spec (and these callbacks, and so the model) as long
  // as the device.
  spec.on_set_feature = [model](const Bytes& r) { model->set_feature(r); };
  spec.on_get_feature = [model](std::uint8_t id, Bytes& reply) { return model->get_feature(id, reply); };
  spec.on_output = [model](const Bytes& r) { model->output(r); };
  return model;
}

void EmulatedPid::answer(int pending, int status) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_ = pending;
  status_ = status;
}

std::int64_t EmulatedPid::field(const Bytes& r, const devices::PidSlot& s) const {
  return devices::read_hid_bits(r.data(), r.size(), s.bit, s.bits, s.min < 0);
}

void EmulatedPid::set_feature(const Bytes& r) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (r.empty() || r[0] != layout_.create_type.report_id) return;
  ++creates_;
  created_any_ = true;
  polls_left_ = pending_;
  last_created_ = 0;
  if (status_ == 2 || status_ == 3) {
    last_status_ = status_ == 2 ? layout_.load_full : layout_.load_error;
    return;
  }
  for (std::size_t k = 0; k < effects_.size(); ++k)
    if (!effects_[k].allocated) {
      effects_[k] = Effect{};
      effects_[k].allocated = true;
      last_created_ = int(k) + 1;
      last_status_ = layout_.load_success;
      return;
    }
  last_status_ = layout_.load_full;
}

bool EmulatedPid::get_feature(std::uint8_t id, Bytes& reply) {
  std::lock_guard<std::mutex> lock(mutex_);
  const devices::PidSlot& load = layout_.load_block;
  if (id == load.report_id) {
    reply.assign(load.report_bytes, 0);
    reply[0] = id;
    if (polls_left_ > 0) {
      --polls_left_;  // status 0: not done yet
      return true;
    }
    put(reply, layout_.load_block, last_created_);
    put(reply, layout_.load_status, last_status_);
    put(reply, layout_.load_ram_available, 0xffff);
    return true;
  }
  const devices::PidSlot& pool = layout_.pool_max_effects;
  if (pool.present && id == pool.report_id) {
    reply.assign(pool.report_bytes, 0);
    reply[0] = id;
    put(reply, layout_.pool_ram_size, 0xffff);
    put(reply, layout_.pool_max_effects, std::int64_t(effects_.size()));
    return true;
  }
  return false;
}

void EmulatedPid::output(const Bytes& r) {
  if (r.empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const double now = steady_now();
  const devices::PidLayout& p = layout_;
  // The effect a report names, or null (and an error) for one the device
  // never gave.
  const auto effect = [&](const devices::PidSlot& slot, const char* report) -> Effect* {
    const std::int64_t index = field(r, slot);
    if (!created_any_) errors_ += std::string(report) + " before any Create New Effect; ";
    if (index < 1 || index > std::int64_t(effects_.size()) || !effects_[std::size_t(index - 1)].allocated) {
      errors_ += std::string(report) + " names block " + std::to_string(index) + ", which the device did not give; ";
      return nullptr;
    }
    return &effects_[std::size_t(index - 1)];
  };
  if (r[0] == p.effect_block.report_id && r.size() == p.effect_block.report_bytes) {
    if (Effect* e = effect(p.effect_block, "Set Effect")) {
      e->set = true;
      e->duration_ms = std::uint32_t(field(r, p.duration));
      e->direction = field(r, p.direction[0]);
    }
  } else if (r[0] == p.constant_block.report_id && r.size() == p.constant_block.report_bytes) {
    if (Effect* e = effect(p.constant_block, "Set Constant Force")) e->magnitude = field(r, p.magnitude);
  } else if (r[0] == p.operation_block.report_id && r.size() == p.operation_block.report_bytes) {
    if (Effect* e = effect(p.operation_block, "Effect Operation")) {
      const std::int64_t op = field(r, p.operation);
      if (op == p.op_start) {
        if (!e->set) errors_ += "Effect Operation Start before its Set Effect; ";
        e->started = now, e->stopped = false;
      } else if (op == p.op_stop) {
        e->stopped = true;
      }
    }
  } else if (p.free_block.present && r[0] == p.free_block.report_id && r.size() == p.free_block.report_bytes) {
    if (Effect* e = effect(p.free_block, "Block Free")) *e = Effect{};
  } else if (r[0] == p.control.report_id && r.size() == p.control.report_bytes) {
    const std::int64_t v = field(r, p.control);
    if (v == p.control_reset) {
      for (Effect& e : effects_) e = Effect{};
    } else if (v == p.control_enable) {
      enabled_ = true;
    } else if (v == p.control_disable) {
      enabled_ = false;
    } else if (v == p.control_stop_all) {
      for (Effect& e : effects_) e.stopped = true;
    } else {
      errors_ += "Device Control value " + std::to_string(v) + " is none of this device's codes; ";
    }
  }
}

std::vector<EmulatedPid::Effect> EmulatedPid::effects() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return effects_;
}

int EmulatedPid::creates() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return creates_;
}

bool EmulatedPid::actuators_enabled() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return enabled_;
}

std::string EmulatedPid::errors() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return errors_;
}

bool EmulatedPid::playing(double now) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const Effect& e : effects_)
    if (e.allocated && e.started >= 0.0 && !e.stopped && now < e.started + e.duration_ms * 1e-3) return true;
  return false;
}

void EmulatedPid::push(double now, bool opposite, double* x, double* y) const {
  std::lock_guard<std::mutex> lock(mutex_);
  *x = *y = 0.0;
  for (const Effect& e : effects_) {
    if (!(e.allocated && e.started >= 0.0 && !e.stopped && now < e.started + e.duration_ms * 1e-3)) continue;
    const double m = double(e.magnitude) / double(layout_.magnitude.max);
    // The direction field's logical range spans 0..360 degrees (OpenFFBoard
    // 0..36000, the Arduino library 0..255); a wheel's is east.
    const double theta = layout_.axes == 1 ? M_PI / 2
                                           : double(e.direction) / double(layout_.direction[0].max) * 2.0 * M_PI;
    const double s = opposite ? -1.0 : 1.0;
    *x += s * m * -std::sin(theta);
    *y += s * m * std::cos(theta);
  }
}

}  // namespace prox::test
