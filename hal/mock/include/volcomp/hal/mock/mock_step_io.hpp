// Mock step I/O: input counters set by the test (or by decoders fed with simulated lines) and
// output plans expanded into line edges that go to a DriveModel per axis and, optionally, to a
// Timeline. Satisfies the StepIo static interface (volcomp/hal/step_io.hpp).
//
// The drive models stand for the drives wired to the outputs: Configure() keeps an axis's model
// (its position and history) while the axis's output format and drive timing stay the same, and
// starts a fresh one for an axis whose format or timing changed.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "volcomp/config/board_config.hpp"
#include "volcomp/hal/mock/drive_model.hpp"
#include "volcomp/hal/mock/timeline.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::hal::mock {

class MockStepIo {
 public:
  /// `config` gives the axes, formats, drive timing and the pulse clock (must be 1 GHz or any
  /// rate; plan times are converted to ns).
  MockStepIo(const BoardConfig& config, Timeline* timeline);

  // StepIo interface.
  Status Configure(const BoardConfig& config);
  void ReadCounters(uint32_t* counters) const;
  void Apply(const PulsePlan* plans);

  /// The start time of the tick whose plans the next Apply() receives.
  void set_tick_start_ns(uint64_t t) { tick_start_ns_ = t; }
  /// Input side: the hardware counter value of an axis (wraps at the configured width).
  void set_counter(uint8_t axis, uint32_t value) { counters_[axis] = value & counter_mask_[axis]; }
  void add_steps(uint8_t axis, int32_t delta) {
    counters_[axis] = (counters_[axis] + static_cast<uint32_t>(delta)) & counter_mask_[axis];
  }

  const DriveModel& drive(uint8_t axis) const { return *drives_[axis]; }
  const std::vector<PulsePlan>& last_plans() const { return last_plans_; }
  uint64_t ticks_applied() const { return ticks_; }
  /// The configuration last applied (the constructor's until Configure()).
  const BoardConfig& config() const { return config_; }
  uint32_t configure_count() const { return configures_; }

 private:
  void Edge(uint8_t axis, uint64_t t, bool line_b, bool level);

  BoardConfig config_;
  Timeline* timeline_;
  uint64_t tick_start_ns_ = 0;
  uint32_t counters_[6] = {};
  uint32_t counter_mask_[6] = {};
  std::vector<std::unique_ptr<DriveModel>> drives_;
  bool line_a_[6] = {};
  bool line_b_[6] = {true, true, true, true, true, true};  // DIR high = positive at power-up
  uint8_t quad_phase_[6] = {};
  std::vector<PulsePlan> last_plans_;
  uint64_t ticks_ = 0;
  uint32_t configures_ = 0;
};

}  // namespace volcomp::hal::mock
