// Tick I/O of a CAN gateway board (tick_io.hpp): the commanded positions of the controller's CSP
// target PDOs in (CspInput), the corrections into the forwarded targets out (CspOutput), both on
// one CspGateway (csp_stages.hpp). Static, no virtual call; the frame routing around the gateway
// is GatewayApp's (gateway_app.hpp).
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/tick_io.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/gateway/csp_stages.hpp"

namespace volcomp::firmware {

class CspIo {
 public:
  /// No step pulses: the settings' drive pulse timing does not concern it.
  static constexpr OutputStage kOutputStage = OutputStage::kCanSetpoints;

  explicit CspIo(gateway::CspGateway* gateway) : input_(gateway), output_(gateway) {}

  /// No step hardware: the output stage only (the gateway's PDO mapping is GatewayApp's).
  Status Configure(const BoardConfig& config) { return output_.Configure(config); }
  void ReadCounters(uint32_t* counters) { input_.ReadCounters(counters); }
  void Output(const ControlTick& tick) { output_.Apply(tick.targets(), tick.corrections()); }
  OutputStatus output_status() const {
    OutputStatus s;
    for (uint8_t a = 0; a < output_.axis_count(); ++a) s.position_steps[a] = output_.position(a);
    return s;
  }

  const gateway::CspOutput& output() const { return output_; }

 private:
  gateway::CspInput input_;
  gateway::CspOutput output_;
};

static_assert(IsTickIo<CspIo>::value, "CspIo must be a tick I/O type");

}  // namespace volcomp::firmware
