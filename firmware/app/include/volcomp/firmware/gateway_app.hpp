// The board application in CAN gateway mode: the CiA 301 node (BoardApp with its object
// dictionary, table store and activation rules) on the controller's bus, and the CiA 402 CSP
// gateway (CspGateway) between the controller's bus and the drives' bus, with the correction
// computed by the same ControlTick / Compensator as in step/dir mode: BoardApp<CspIo>, whose input
// stage is the commanded positions from the target PDOs and whose output stage is the correction
// of the forwarded targets (csp_io.hpp).
//
//   OnControllerFrame()  a frame received on the controller side: forwarded to the drives with
//                        corrected targets; NMT and the board's own SDO requests also go to the
//                        node (its answers are sent on the controller side).
//   OnDriveFrame()       a frame received on the drive side: forwarded with corrected actuals.
//   Tick()               the control tick (BoardSettings::board.tick_hz): BoardApp::Tick(), whose
//                        output stage hands the new corrections to the gateway.
//   Poll()               the main loop: slow lines and the node (SDO, NMT, heartbeat, EMCY).
//
// Without a drive port (`drives` null) the board is a plain CANopen node (no forwarding).
// Freestanding (no heap: the node's frame queue is a fixed ring inside the object); the devices
// are HAL interfaces, so tests run it on the mock HAL, volcomp-fw-linux on SocketCAN, files and
// GPIO, and the STM32G474 gateway image on FDCAN1 / FDCAN2.
//
// Thread-safety: OnControllerFrame, OnDriveFrame, PumpFrames and Poll from one context (the main
// loop). Tick() either from the same thread (Linux) or from the tick ISR, which may preempt the
// main loop but is never preempted by it (MCU): the tick touches only BoardApp's tick data and the
// gateway's per-axis atomic words (csp_gateway.hpp).
#pragma once

#include <cstdint>

#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/csp_io.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/temperature_inputs.hpp"
#include "volcomp/hal/tick_timer.hpp"

namespace volcomp::firmware {

struct GatewayDevices {
  hal::CanPort* controller = nullptr;    // CNC side (required): the board's node lives here
  hal::CanPort* drives = nullptr;        // drive side (optional: no gateway without it)
  hal::SlowIo* io = nullptr;             // required
  hal::Flash* table_flash = nullptr;     // required: the dual-bank table store
  hal::Flash* settings_flash = nullptr;  // optional: settings stored with 0x1010
  hal::Clock* clock = nullptr;           // required
  hal::TickTimer* tick_timer = nullptr;  // optional: the timer that calls Tick() (the board
                                         // application sets its rate: BoardApp::Devices)
  hal::TemperatureInputs* temperatures = nullptr;  // optional: the board's own temperature
                                                   // sensors (BoardApp::Devices)
};

/// Counters of the glue (the gateway's own counters are in gateway().counters()).
struct GatewayAppCounters {
  uint32_t forwarded_to_drives = 0;
  uint32_t forwarded_to_controller = 0;
  uint32_t send_failures = 0;  // a forward refused by the port (queue full): frame lost
  uint32_t node_overruns = 0;  // node frames dropped because the node queue was full
};

class GatewayApp {
 public:
  using App = BoardApp<CspIo>;

  explicit GatewayApp(const GatewayDevices& devices);
  GatewayApp(const GatewayApp&) = delete;
  GatewayApp& operator=(const GatewayApp&) = delete;

  /// Starts the board (stored settings override `defaults`) and the gateway with `gateway`
  /// (own_node_id is taken from the settings in force). kConfigInvalid when the settings or the
  /// gateway mapping are invalid for the axis count in force.
  Status Start(const BoardSettings& defaults,
               const gateway::GatewayConfig& gateway,
               const AppOptions& options = AppOptions());

  gateway::Route OnControllerFrame(const CanFrame& frame);
  gateway::Route OnDriveFrame(const CanFrame& frame);
  void Tick();
  /// Tick() timed with the clock (BoardApp::TimedTick(): diagnostic object 0x2140).
  void TimedTick();
  void Poll();

  /// Receives and handles every frame waiting on both ports (tests and simple loops; the Linux
  /// runner calls OnControllerFrame / OnDriveFrame itself to time each frame).
  void PumpFrames();

  App& app() { return app_; }
  const App& app() const { return app_; }
  const gateway::CspGateway& gateway() const { return gateway_; }
  const GatewayAppCounters& counters() const { return counters_; }
  bool gateway_active() const { return devices_.drives != nullptr && gateway_ok_; }
  /// True when frames for the node are waiting (call Poll() soon for a prompt SDO answer).
  bool node_pending() const { return !node_port_.empty(); }

 private:
  // The node's CAN port: frames for the node are queued here by OnControllerFrame (a fixed ring);
  // what the node sends goes out on the controller port.
  class NodePort final : public hal::CanPort {
   public:
    explicit NodePort(hal::CanPort* controller) : controller_(controller) {}
    bool Push(const CanFrame& f);
    bool empty() const { return count_ == 0; }

   private:
    static constexpr uint32_t kCapacity = 256;
    Status DoSend(const CanFrame& frame) override;
    Status DoSetBitrate(uint32_t bitrate_bps) override;
    bool DoReceive(CanFrame* frame) override;

    hal::CanPort* controller_;
    CanFrame ring_[kCapacity];
    uint32_t head_ = 0;
    uint32_t count_ = 0;
  };

  void SyncGatewayWithSettings();

  // Construction order matters: the tick I/O and the node port exist before the app that uses
  // them.
  GatewayDevices devices_;
  gateway::CspGateway gateway_;
  gateway::GatewayConfig gateway_config_;
  bool gateway_ok_ = false;
  uint8_t gateway_node_id_ = 0;
  uint8_t gateway_axes_ = 0;
  CspIo tick_io_;
  NodePort node_port_;
  App app_;
  GatewayAppCounters counters_;
};

}  // namespace volcomp::firmware
