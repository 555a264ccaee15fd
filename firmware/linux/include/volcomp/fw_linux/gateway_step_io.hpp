// The StepIo of the board application in gateway mode: there are no step inputs and outputs; the
// "input counters" are the commanded positions the CSP gateway reads from the controller's target
// PDOs (CspGateway::InputCounter, drive increments in machine direction, wrapping 32-bit), and the
// output plans are not used (the correction reaches the drives inside the forwarded PDOs).
// So the same ControlTick / Compensator as in step/dir mode computes the correction.
#pragma once

#include <cstdint>

#include "volcomp/csp_gateway.hpp"
#include "volcomp/hal/step_io.hpp"
#include "volcomp/step_generator.hpp"

namespace volcomp::fw_linux {

class GatewayStepIo {
 public:
  explicit GatewayStepIo(const gateway::CspGateway* gateway) : gateway_(gateway) {}

  /// Nothing to set up: no step lines (the gateway follows the axis count in force itself).
  Status Configure(const BoardConfig& /*config*/) { return Status::Ok(); }

  void ReadCounters(uint32_t* counters) {
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) counters[a] = gateway_->InputCounter(a);
  }
  void Apply(const PulsePlan* /*plans*/) {}

 private:
  const gateway::CspGateway* gateway_;
};

static_assert(hal::IsStepIo<GatewayStepIo>::value, "GatewayStepIo must be a StepIo");

}  // namespace volcomp::fw_linux
