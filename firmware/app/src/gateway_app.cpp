// The board application in CAN gateway mode.
#include "volcomp/firmware/gateway_app.hpp"

namespace volcomp::firmware {

bool GatewayApp::NodePort::Push(const CanFrame& f) {
  if (count_ == kCapacity) return false;
  ring_[(head_ + count_) % kCapacity] = f;
  ++count_;
  return true;
}

Status GatewayApp::NodePort::DoSend(const CanFrame& frame) { return controller_->Send(frame); }

// The node's bit rate is the controller bus's.
Status GatewayApp::NodePort::DoSetBitrate(uint32_t bitrate_bps) {
  return controller_->SetBitrate(bitrate_bps);
}

bool GatewayApp::NodePort::DoReceive(CanFrame* frame) {
  if (count_ == 0) return false;
  *frame = ring_[head_];
  head_ = (head_ + 1) % kCapacity;
  --count_;
  return true;
}

GatewayApp::GatewayApp(const GatewayDevices& devices)
    : devices_(devices),
      tick_io_(&gateway_),
      node_port_(devices.controller),
      app_(App::Devices{&tick_io_, devices.io, devices.table_flash, devices.settings_flash,
                        &node_port_, devices.clock, devices.tick_timer}) {}

Status GatewayApp::Start(const BoardSettings& defaults,
                         const gateway::GatewayConfig& gateway,
                         const AppOptions& options) {
  if (devices_.controller == nullptr || devices_.io == nullptr || devices_.table_flash == nullptr ||
      devices_.clock == nullptr) {
    return Error::kInvalidArgument;
  }
  gateway_config_ = gateway;
  gateway_ok_ = false;
  gateway_node_id_ = gateway_axes_ = 0;
  VOLCOMP_TRY(app_.Start(defaults, options));
  SyncGatewayWithSettings();
  return gateway_ok_ || devices_.drives == nullptr ? Status::Ok() : Status(Error::kConfigInvalid);
}

// The gateway follows the settings in force: the node-ID (frames for the board's own SDO server)
// and the axis count (mapped axes must exist). Settings change only at a node reset, so this
// reconfigures (and restarts the commanded positions) only then.
void GatewayApp::SyncGatewayWithSettings() {
  const uint8_t node = app_.settings().node_id;
  const uint8_t axes = app_.control_tick().axis_count();
  if (node == gateway_node_id_ && axes == gateway_axes_) return;
  gateway_node_id_ = node;
  gateway_axes_ = axes;
  gateway::GatewayConfig c = gateway_config_;
  c.own_node_id = node;
  gateway_ok_ = gateway_.Configure(c, axes).ok();
}

gateway::Route GatewayApp::OnControllerFrame(const CanFrame& frame) {
  CanFrame out = frame;
  gateway::Route route = gateway::Route::kForward;
  if (app_.node().IsRpdo(frame)) {
    route = gateway::Route::kLocal;  // the board's own RPDOs (bit 31 set never matches)
  } else if (gateway_ok_) {
    route = gateway_.FromController(frame, &out);
  } else if (!frame.extended && frame.id == 0x600u + app_.settings().node_id) {
    route = gateway::Route::kLocal;
  }
  // The node needs NMT commands, its own SDO requests and its RPDOs; nothing else reaches it.
  if (!frame.extended && !frame.rtr && (frame.id == 0 || route == gateway::Route::kLocal)) {
    if (!node_port_.Push(frame)) ++counters_.node_overruns;
  }
  if (route == gateway::Route::kForward && devices_.drives != nullptr) {
    if (devices_.drives->Send(out).ok()) {
      ++counters_.forwarded_to_drives;
    } else {
      ++counters_.send_failures;
    }
  }
  return route;
}

gateway::Route GatewayApp::OnDriveFrame(const CanFrame& frame) {
  CanFrame out = frame;
  const gateway::Route route =
      gateway_ok_ ? gateway_.FromDrive(frame, &out) : gateway::Route::kForward;
  if (route == gateway::Route::kForward) {
    if (devices_.controller->Send(out).ok()) {
      ++counters_.forwarded_to_controller;
    } else {
      ++counters_.send_failures;
    }
  }
  return route;
}

void GatewayApp::Tick() { app_.Tick(); }
void GatewayApp::TimedTick() { app_.TimedTick(); }

void GatewayApp::Poll() {
  app_.Poll();
  SyncGatewayWithSettings();
}

void GatewayApp::PumpFrames() {
  CanFrame f;
  while (devices_.controller->Receive(&f)) OnControllerFrame(f);
  if (devices_.drives == nullptr) return;
  while (devices_.drives->Receive(&f)) OnDriveFrame(f);
}

}  // namespace volcomp::firmware
