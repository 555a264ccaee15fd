// A PC-tool session with one volcomp node over a real transport (SocketCAN, SLCAN, SLCAN-TCP):
// typed object access (NodeObjects) and the node's heartbeat and EMCY frames observed on the way.
// Failures of the link are kCommunication (can_io/transport.hpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/can_io/transport.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::canopen_client {

using canopen::NmtCommand;  // lib/canopen/node.hpp

class CanSession : public NodeObjects {
 public:
  /// Opens `spec` (see can_io::OpenTransport), logging every frame to `log_path` if not empty.
  /// The failure is the transport's (or kIoError when the log cannot be written).
  static Expected<std::unique_ptr<CanSession>> Open(const std::string& spec,
                                                    uint8_t node,
                                                    const std::string& log_path = "",
                                                    SdoClient::Options options = {});
  CanSession(const CanSession&) = delete;
  CanSession& operator=(const CanSession&) = delete;

  can_io::CanTransport& transport() { return *transport_; }
  /// The frames a session needs from the bus (the transport's kernel filter on SocketCAN): this
  /// node's SDO responses and EMCY, and every node's heartbeat and boot-up (a reset node may come
  /// back with another node-ID).
  static std::vector<can_io::ReceiveFilter> ReceiveFilters(uint8_t node);

  /// Receives for `duration`, recording heartbeats and EMCY (monitoring, waiting for a state).
  Outcome Listen(std::chrono::milliseconds duration);
  /// NMT state from the last heartbeat or boot-up seen, if any.
  std::optional<uint8_t> nmt_state() const { return nmt_state_; }
  /// EMCY frames seen since the last TakeEmcy().
  std::vector<CanFrame> TakeEmcy();
  /// Sends an NMT command (cs) to this node.
  Outcome SendNmt(uint8_t command);
  Outcome SendNmt(NmtCommand command) { return SendNmt(static_cast<uint8_t>(command)); }
  /// Receives for up to `timeout` until node `expected` sends its boot-up message (0x700 + id,
  /// data 00) and returns `expected`; when the time passes without it, the id of another node
  /// whose boot-up was seen meanwhile (a reset node comes back with its stored node-ID), else none.
  Expected<std::optional<uint8_t>> WaitForBootUp(uint8_t expected,
                                                 std::chrono::milliseconds timeout);
  /// Receives for up to `timeout` until this node sends a heartbeat or its boot-up message (state
  /// 0); returns that state, none when nothing came from it.
  Expected<std::optional<uint8_t>> WaitForHeartbeat(std::chrono::milliseconds timeout);
  /// Receives for up to `timeout` until this node's heartbeat reports `state`; returns the state of
  /// the last heartbeat received meanwhile (none when no heartbeat came).
  Expected<std::optional<uint8_t>> WaitForState(uint8_t state, std::chrono::milliseconds timeout);

 private:
  CanSession(std::unique_ptr<can_io::CanTransport> transport,
             uint8_t node,
             SdoClient::Options options);
  void Observe(const CanFrame& f);
  // Receives (observing every frame) until `done` accepts a frame (true) or `timeout` passes.
  Expected<bool> ReceiveUntil(std::chrono::milliseconds timeout,
                              const std::function<bool(const CanFrame&)>& done);

  // "N received frames were dropped ..." when the transport lost frames since the last call.
  std::string DescribeDrops();

  FrameLink link_;  // what NodeObjects talks through (bound before it is filled in)
  std::unique_ptr<can_io::CanTransport> transport_;
  uint64_t drops_reported_ = 0;
  std::optional<uint8_t> nmt_state_;
  std::vector<CanFrame> emcy_;
};

/// Readable description of a heartbeat state byte ("pre-operational", ...).
std::string NmtStateName(uint8_t state);

}  // namespace volcomp::canopen_client
