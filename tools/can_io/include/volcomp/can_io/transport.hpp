// CanTransport: the PC tool's and the simulator's connection to a CAN bus, and OpenTransport(),
// which builds one from a spec string:
//   socketcan:IFACE                    Linux SocketCAN raw socket (e.g. socketcan:can0)
//   slcan:DEVICE[@BITRATE]             SLCAN adapter on a serial device or pty
//   slcan-tcp:HOST:PORT[@BITRATE]      SLCAN over TCP (e.g. the simulator's SlcanServer)
// BITRATE is bit/s with an optional k/M suffix (500k, 1M, 1000000) and must be in the SLCAN S0..S9
// table; without it the adapter keeps its configured bitrate. See docs/can-transports.md.
//
// Errors: a Failure whose message names the spec and the cause: kInvalidArgument for a bad spec or
// frame, kCommunication for everything the link does (unreachable endpoint, closed connection,
// adapter refusal, transmit timeout, bus-off). Thread-safety: one thread at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::can_io {

/// Something the bus or adapter reported besides frames: error frames and state changes
/// (SocketCAN), error replies (SLCAN BEL).
struct BusEvent {
  enum class Kind : uint8_t {
    kErrorFrame,    // SocketCAN error frame without a state change (bus error, no ack, ...)
    kErrorWarning,  // controller reached the warning level
    kErrorPassive,  // controller is error-passive
    kBusOff,        // controller is bus-off (it sends and acknowledges nothing)
    kErrorActive,   // controller is back to error-active (e.g. after a restart)
    kAdapterError,  // SLCAN adapter answered BEL to a command or frame
  };
  Kind kind = Kind::kErrorFrame;
  std::string text;  // readable description
};

class CanTransport {
 public:
  virtual ~CanTransport() = default;

  /// Transmits one frame (blocks only while the adapter or the interface queue is full, up to
  /// the transport's send timeout). kInvalidArgument for an invalid frame, kCommunication when
  /// the link fails or the controller is bus-off.
  virtual Outcome Send(const CanFrame& frame) = 0;
  /// The next received frame, or nullopt when none arrived within `timeout` (0 = poll);
  /// kCommunication when the link is gone (connection closed, device removed).
  virtual Expected<std::optional<CanFrame>> Receive(std::chrono::microseconds timeout) = 0;
  /// What this transport is connected to, e.g. "slcan-tcp:127.0.0.1:29536 @1000000".
  virtual std::string description() const = 0;
  /// Events seen since the last call (oldest first).
  virtual std::vector<BusEvent> TakeEvents() { return {}; }
  /// Received frames lost before this program read them, since the transport was opened (a
  /// kernel receive buffer that was full: a process that did not run for a while on a busy bus);
  /// 0 where the transport cannot tell.
  virtual uint64_t dropped_frames() const { return 0; }
};

/// A received standard (11-bit) frame is wanted when (id & mask) == (this id & mask).
struct ReceiveFilter {
  uint16_t id = 0;
  uint16_t mask = 0x7FF;
};

struct TransportOptions {
  /// The frames this program needs; empty: all. SocketCAN lets the kernel drop the others before
  /// they take room in the receive buffer (a session with one node on a bus full of PDOs);
  /// SLCAN receives everything the adapter sends (the caller ignores what it does not need).
  std::vector<ReceiveFilter> receive;
};

/// A parsed transport spec.
struct TransportSpec {
  enum class Kind : uint8_t { kSocketCan, kSlcanSerial, kSlcanTcp };
  Kind kind = Kind::kSocketCan;
  std::string target;    // interface, device path, or host
  uint16_t port = 0;     // kSlcanTcp
  uint32_t bitrate = 0;  // SLCAN: 0 = do not send S<n>
};

/// Parses a spec (forms above); kInvalidArgument explaining the accepted forms.
Expected<TransportSpec> ParseTransportSpec(const std::string& spec);
/// Parses "500000", "500k", "1M" into bit/s; kInvalidArgument when not in the SLCAN table.
Expected<uint32_t> ParseBitrate(const std::string& text);

/// Opens the transport a spec names. The failure says what to do, e.g. "socketcan:
/// socket(AF_CAN): address family not supported: this kernel has no CAN support (try
/// slcan-tcp:HOST:PORT against a simulator, or run inside user-mode-linux)" (kCommunication).
Expected<std::unique_ptr<CanTransport>> OpenTransport(const std::string& spec,
                                                      const TransportOptions& options = {});

}  // namespace volcomp::can_io
