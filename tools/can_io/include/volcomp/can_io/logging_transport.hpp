// LoggingTransport: a CanTransport decorator that records every frame sent (" T") and received
// (" R") in candump -L format (the PC tool's --log FILE). Frames are logged after a successful
// Send() and when Receive() returns them; failures are the wrapped transport's.
//
// Thread-safety: as the wrapped transport (one thread at a time).
#pragma once

#include <memory>
#include <string>

#include "volcomp/can_io/candump_log.hpp"
#include "volcomp/can_io/transport.hpp"

namespace volcomp::can_io {

class LoggingTransport : public CanTransport {
 public:
  /// Both must be set.
  LoggingTransport(std::unique_ptr<CanTransport> inner, std::unique_ptr<CandumpLogWriter> log);

  Outcome Send(const CanFrame& frame) override;
  Expected<std::optional<CanFrame>> Receive(std::chrono::microseconds timeout) override;
  std::string description() const override;
  std::vector<BusEvent> TakeEvents() override { return inner_->TakeEvents(); }
  uint64_t dropped_frames() const override { return inner_->dropped_frames(); }

  CanTransport& inner() { return *inner_; }
  CandumpLogWriter& log() { return *log_; }

 private:
  std::unique_ptr<CanTransport> inner_;
  std::unique_ptr<CandumpLogWriter> log_;
};

/// The interface column to write for a spec: the interface for socketcan:IFACE, "slcan0" for the
/// SLCAN forms (what the kernel's slcan driver would call it).
Expected<std::string> LogInterfaceName(const std::string& spec);

/// OpenTransport(spec, options), wrapped in a LoggingTransport writing to `log_path` when it is
/// not empty (kIoError when the log cannot be written). The log has the frames the transport
/// passes on: with options.receive set, only those (and every frame sent).
Expected<std::unique_ptr<CanTransport>> OpenTransportWithLog(const std::string& spec,
                                                             const std::string& log_path,
                                                             const TransportOptions& options = {});

}  // namespace volcomp::can_io
