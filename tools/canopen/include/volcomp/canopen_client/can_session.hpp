// A PC-tool session with one volcomp node over a real transport (SocketCAN, SLCAN, SLCAN-TCP):
// typed object access by ObjectId (addresses and sizes from the shared object dictionary), and
// the node's heartbeat and EMCY frames observed on the way.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/can_io/transport.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/sdo_runner.hpp"

namespace volcomp::canopen_client {

class CanSession {
 public:
  /// Opens `spec` (see can_io::OpenTransport), logging every frame to `log_path` if not empty.
  /// Throws std::runtime_error when the transport cannot be opened.
  CanSession(const std::string& spec,
             uint8_t node,
             const std::string& log_path = "",
             SdoClient::Options options = {});

  uint8_t node() const { return node_; }
  const FrameLink& link() const { return link_; }
  const SdoClient::Options& options() const { return options_; }
  can_io::CanTransport& transport() { return *transport_; }

  SdoResult Write(canopen::ObjectId id, uint32_t value);
  SdoResult Read(canopen::ObjectId id, uint32_t* value);
  SdoResult ReadString(canopen::ObjectId id, std::string* value);
  SdoResult Download(canopen::ObjectId id,
                     const std::vector<uint8_t>& data,
                     std::function<void(uint32_t, uint32_t)> progress = {});
  SdoResult UploadDomain(canopen::ObjectId id, std::vector<uint8_t>* data);

  /// Receives for `duration`, recording heartbeats and EMCY (monitoring, waiting for a state).
  void Listen(std::chrono::milliseconds duration);
  /// NMT state from the last heartbeat or boot-up seen, if any.
  std::optional<uint8_t> nmt_state() const { return nmt_state_; }
  /// EMCY frames seen since the last TakeEmcy().
  std::vector<CanFrame> TakeEmcy();
  /// Sends an NMT command (cs) to this node.
  void SendNmt(uint8_t command);

 private:
  void Observe(const CanFrame& f);

  uint8_t node_;
  SdoClient::Options options_;
  std::unique_ptr<can_io::CanTransport> transport_;
  FrameLink link_;
  std::optional<uint8_t> nmt_state_;
  std::vector<CanFrame> emcy_;
};

/// Readable description of a heartbeat state byte ("pre-operational", ...).
std::string NmtStateName(uint8_t state);

}  // namespace volcomp::canopen_client
