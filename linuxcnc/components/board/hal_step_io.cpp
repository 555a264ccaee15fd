// Step I/O on HAL pins: decoding and waveform sampling (see the header).
#include "board/hal_step_io.hpp"

namespace volcomp::linuxcnc {

void HalStepIo::Configure(bool invert_input_dir, bool dir_negative_high) {
  for (auto& d : decoder_) d = StepDecoder(PulseFormat::kStepDir, invert_input_dir);
  dir_negative_high_ = dir_negative_high;
  for (uint8_t a = 0; a < kAxes; ++a) dir_level_[a] = !dir_negative_high;
}

void HalStepIo::SampleInputs(const bool* step, const bool* dir) {
  for (uint8_t a = 0; a < kAxes; ++a) {
    counter_[a] += static_cast<uint32_t>(decoder_[a].Sample(step[a], dir[a]));
  }
}

void HalStepIo::ReadCounters(uint32_t* counters) const {
  for (uint8_t a = 0; a < kAxes; ++a) counters[a] = counter_[a];
}

uint32_t HalStepIo::decode_errors() const {
  uint32_t n = 0;
  for (const auto& d : decoder_) n += d.errors();
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
  for (uint8_t a = 0; a < kAxes; ++a) {
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
        if (e.level && !step_level_[a]) ++rendered_[a];
        step_level_[a] = e.level;
      }
      ++head_[a];
    }
    step[a] = step_level_[a];
    dir[a] = dir_level_[a];
  }
}

}  // namespace volcomp::linuxcnc
