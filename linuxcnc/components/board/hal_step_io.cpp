// Step I/O on HAL pins: sampled input counters and the sampled output waveform (see the header).
#include "board/hal_step_io.hpp"

namespace volcomp::linuxcnc {

Status HalStepIo::Configure(const BoardConfig& config) {
  if (period_ns_ == 0 || config.axis_count == 0 || config.axis_count > kAxes ||
      config.pulse_clock_hz != 1000000000u) {
    return Error::kConfigInvalid;
  }
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    const AxisConfig& x = config.axis[a];
    if (x.input_format != PulseFormat::kStepDir || x.output_format != PulseFormat::kStepDir) {
      return Error::kConfigInvalid;
    }
    const DriveTiming& d = x.drive;
    if (d.pulse_width_ns < period_ns_ || d.step_space_ns < period_ns_ ||
        d.dir_setup_ns < period_ns_ || d.dir_hold_ns < period_ns_) {
      return Error::kConfigInvalid;  // a phase shorter than a period can fall between samples
    }
    // A tick's edges (two per pulse and a direction edge), and those of the tick before that
    // are still to be rendered, must fit the queue.
    const Result<PulseTiming> t = PulseTiming::FromDrive(x, config.tick_hz, config.pulse_clock_hz);
    if (!t.ok()) return t.status();
    if (2 * (2 * t->max_per_tick + 1) > kQueue) return Error::kConfigInvalid;
  }
  axis_count_ = config.axis_count;
  for (uint8_t a = 0; a < kAxes; ++a) {
    const uint8_t bits = a < axis_count_ ? config.axis[a].input_counter_bits : 32;
    counter_mask_[a] = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u;
    counter_[a].Reset(a < axis_count_ && config.axis[a].invert_input_dir, in_step_[a], in_dir_[a]);
    head_[a] = tail_[a] = 0;
    step_level_[a] = false;
    dir_level_[a] = !dir_negative_high_;  // the output stage restarts moving positive
  }
  return Status::Ok();
}

void HalStepIo::SampleInputs(const bool* step, const bool* dir) {
  for (uint8_t a = 0; a < kAxes; ++a) {
    counter_[a].Sample(step[a], dir[a]);
    in_step_[a] = step[a];
    in_dir_[a] = dir[a];
  }
}

void HalStepIo::ReadCounters(uint32_t* counters) const {
  for (uint8_t a = 0; a < axis_count_; ++a) counters[a] = counter_[a].count() & counter_mask_[a];
}

uint32_t HalStepIo::decode_errors() const {
  uint32_t n = 0;
  for (const auto& c : counter_) n += c.setup_violations();
  return n;
}

void HalStepIo::Push(uint8_t a, const Edge& e) {
  if (tail_[a] - head_[a] >= kQueue) {
    ++overflows_;
    return;
  }
  queue_[a][tail_[a] % kQueue] = e;
  ++tail_[a];
}

void HalStepIo::Apply(const PulsePlan* plans) {
  for (uint8_t a = 0; a < axis_count_; ++a) {
    const PulsePlan& p = plans[a];
    const bool dir_level = p.negative == dir_negative_high_;
    if (p.dir_change) Push(a, {tick_start_ns_ + p.dir_edge, true, dir_level});
    for (uint32_t i = 0; i < p.count; ++i) {
      const int64_t rise = tick_start_ns_ + p.first_rise + int64_t{i} * p.period;
      Push(a, {rise, false, true});
      Push(a, {rise + p.width, false, false});
    }
  }
}

void HalStepIo::Render(int64_t now_ns, bool* step, bool* dir) {
  for (uint8_t a = 0; a < kAxes; ++a) {
    // Edges of one line are queued in time order; the two lines' edges interleave in plan order,
    // which is time order too (direction edges come between pulses).
    while (head_[a] != tail_[a] && queue_[a][head_[a] % kQueue].t_ns <= now_ns) {
      const Edge& e = queue_[a][head_[a] % kQueue];
      if (e.dir_line) {
        dir_level_[a] = e.level;
      } else {
        rendered_[a] += static_cast<int64_t>(e.level && !step_level_[a]);
        step_level_[a] = e.level;
      }
      ++head_[a];
    }
    step[a] = step_level_[a];
    dir[a] = dir_level_[a];
  }
}

}  // namespace volcomp::linuxcnc
