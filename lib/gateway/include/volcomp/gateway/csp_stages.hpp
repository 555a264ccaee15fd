// The control tick's two ends in CAN gateway mode, peers of the step/dir ones (the hardware step
// counters and StepOutput):
//
//   CspInput   input stage: each axis's commanded position, taken from the controller's CiA 402
//              target PDOs by the gateway (CspGateway::InputCounter: drive increments in machine
//              direction, a wrapping 32-bit counter), read as the tick's input counters.
//   CspOutput  output stage: each axis's correction of this tick (ControlTick::corrections())
//              goes into every target forwarded from now on (CspGateway::SetCorrection), so the
//              drive receives the controller's target + correction: the tick's target.
//
// Units: one drive increment is one machine step (the gateway's contract, csp_gateway.hpp).
// Both are called from the control tick (they may preempt the gateway's frame handling: see
// CspGateway's thread-safety notes). O(axes), no division, no allocation.
#pragma once

#include <cstdint>

#include "volcomp/config/board_config.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::gateway {

class CspInput {
 public:
  explicit CspInput(const CspGateway* gateway) : gateway_(gateway) {}

  /// counters[a] for every possible axis (table::kMaxAxes); axes without a target yet read 0.
  void ReadCounters(uint32_t* counters) const {
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) counters[a] = gateway_->InputCounter(a);
  }

 private:
  const CspGateway* gateway_;
};

class CspOutput {
 public:
  explicit CspOutput(CspGateway* gateway) : gateway_(gateway) {}

  /// Takes the axis count of `config` (the gateway's PDO mapping is configured on the gateway
  /// itself) and forgets the positions sent; kConfigInvalid for more than table::kMaxAxes axes.
  Status Configure(const BoardConfig& config) {
    axis_count_ = 0;
    if (config.axis_count > table::kMaxAxes) return Error::kConfigInvalid;
    for (int32_t& p : position_) p = 0;
    axis_count_ = config.axis_count;
    return Status::Ok();
  }

  /// One tick: the correction of each axis for the targets forwarded from now on; the targets
  /// themselves are kept for position().
  void Apply(const int32_t* target_steps, const int32_t* correction_steps) {
    for (uint8_t a = 0; a < axis_count_; ++a) {
      gateway_->SetCorrection(a, correction_steps[a]);
      position_[a] = target_steps[a];
    }
  }

  uint8_t axis_count() const { return axis_count_; }
  /// The target of the last tick: commanded position + correction, what the next forwarded
  /// target of the axis carries (machine steps).
  int32_t position(uint8_t a) const { return position_[a]; }

 private:
  CspGateway* gateway_;
  uint8_t axis_count_ = 0;
  int32_t position_[table::kMaxAxes] = {};
};

}  // namespace volcomp::gateway
