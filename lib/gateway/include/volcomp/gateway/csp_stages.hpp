// The control tick's two ends in CAN gateway mode, peers of the step/dir ones: CspInput reads each
// axis's commanded position from the controller's targets (CspGateway::InputCounter: drive
// increments, a wrapping 32-bit counter) as the tick's input counters; CspOutput hands the tick's
// corrections (ControlTick::corrections()) to every target forwarded from then on
// (CspGateway::SetCorrection). Called from the control tick (may preempt the frame handling);
// O(axes), no division, no allocation. docs/linux-board.md, "How the gateway works".
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
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
