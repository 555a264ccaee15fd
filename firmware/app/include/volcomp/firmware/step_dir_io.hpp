// Tick I/O of a step/dir board (tick_io.hpp): the hardware input step counters in, the step/dir
// output stage (StepOutput: one pulse plan per axis and tick) out through the HAL's StepIo
// (hal/step_io.hpp: Configure, ReadCounters, Apply). Static, no virtual call; Output() is part of
// the tick ISR (on the STM32G474 the object lives in CCM SRAM next to BoardApp).
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/tick_io.hpp"
#include "volcomp/hal/step_io.hpp"
#include "volcomp/output/step_generator.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::firmware {

template <class StepIo>
class StepDirIo {
  static_assert(hal::IsStepIo<StepIo>::value,
                "StepIo must provide Configure(), ReadCounters() and Apply()");

 public:
  /// Its settings keep the step output's rules too (kPulseTiming).
  static constexpr OutputStage kOutputStage = OutputStage::kStepPulses;

  explicit StepDirIo(StepIo* step_io) : step_io_(step_io) {}

  /// The step I/O hardware first (formats, counter widths, pulse clock, tick length: what the
  /// board cannot do is refused there), then the step generators of the output stage.
  Status Configure(const BoardConfig& config) {
    VOLCOMP_TRY(step_io_->Configure(config));
    return output_.Configure(config);
  }
  void ReadCounters(uint32_t* counters) { step_io_->ReadCounters(counters); }
  /// Plans this tick's pulses toward the targets and programs the outputs: axis by axis where the
  /// step I/O has ApplyAxis() (the STM32: each plan goes from registers to its timer), else all
  /// plans, then Apply().
  __attribute__((always_inline)) void Output(const ControlTick& tick) {
    if constexpr (hal::HasApplyAxis<StepIo>::value) {
      StepIo* const io = step_io_;
      output_.PlanEach(tick.targets(),
                       [io](uint32_t a, const PulsePlan& plan) { io->ApplyAxis(a, plan); });
    } else {
      output_.Plan(tick.targets(), plans_);
      step_io_->Apply(plans_);
    }
  }
  OutputStatus output_status() const {
    OutputStatus s;
    for (uint8_t a = 0; a < output_.axis_count(); ++a) {
      s.position_steps[a] = output_.position(a);
      s.max_backlog_steps[a] = output_.max_backlog(a);
    }
    s.overruns = output_.overruns();
    return s;
  }

  /// The output stage (positions, backlog, generators).
  const StepOutput& output() const { return output_; }
  StepIo& step_io() { return *step_io_; }

 private:
  StepIo* step_io_;
  StepOutput output_;
  PulsePlan plans_[table::kMaxAxes];  // Output()'s plans for Apply() (step I/O without ApplyAxis)
};

}  // namespace volcomp::firmware
