// SLCAN client: a CanTransport talking the Lawicel ASCII protocol to an adapter on a serial
// device / pty, or over TCP (e.g. the simulator's SlcanServer).
//
// Opening sends "C\r", "S<n>\r" (when a bitrate is given) and "O\r", then waits up to
// `open_timeout` for the answers: a BEL answer to S or O is a failure (adapter refused); adapters
// that do not answer at all are tolerated. Afterwards "\r", "z" and "Z" acknowledgements are
// ignored; a BEL becomes a BusEvent::kAdapterError. Device timestamps on received frames are
// ignored. Link failures are kCommunication (transport.hpp).
//
// Thread-safety: one thread at a time.
#pragma once

#include <chrono>
#include <deque>
#include <memory>
#include <string>

#include "volcomp/can/slcan.hpp"
#include "volcomp/can_io/transport.hpp"

namespace volcomp::can_io {

struct SlcanOptions {
  uint32_t bitrate = 0;  // bit/s; 0 = keep the adapter's (no S command)
  std::chrono::milliseconds open_timeout{300};
  std::chrono::milliseconds send_timeout{2000};  // adapter not accepting bytes this long: fail
};

class SlcanTransport : public CanTransport {
 public:
  /// Takes ownership of `fd` (connected, any blocking mode; closed on failure too) and runs the
  /// open sequence. `description` names the link in messages ("slcan:/dev/ttyACM0").
  static Expected<std::unique_ptr<SlcanTransport>> Open(int fd,
                                                        std::string description,
                                                        const SlcanOptions& options);
  ~SlcanTransport() override;
  SlcanTransport(const SlcanTransport&) = delete;
  SlcanTransport& operator=(const SlcanTransport&) = delete;

  Outcome Send(const CanFrame& frame) override;
  Expected<std::optional<CanFrame>> Receive(std::chrono::microseconds timeout) override;
  std::string description() const override;
  std::vector<BusEvent> TakeEvents() override;

  /// Sends a raw command line (without '\r') and returns the adapter's answer line (a reply like
  /// "F00"/"V0100", "" for a bare '\r' OK); a BEL or no answer in time is a failure. Frames
  /// arriving meanwhile are queued for Receive().
  Expected<std::string> Command(const std::string& line, std::chrono::milliseconds timeout);

 private:
  SlcanTransport(int fd, std::string description, const SlcanOptions& options);
  // The C / S<n> / O sequence.
  Outcome OpenChannel();
  // Sends one line of the open sequence and checks its answer (`what` null: any answer is fine).
  Outcome OpenStep(const std::string& line, const char* what, bool* answers);
  // Reads what is available (waiting up to `timeout` for the first byte) and decodes it.
  Outcome ReadInput(std::chrono::microseconds timeout);
  void Handle(const slcan::Message& m);

  int fd_;
  std::string description_;
  SlcanOptions options_;
  slcan::Decoder decoder_{slcan::Role::kHost};
  std::deque<CanFrame> rx_;
  std::vector<BusEvent> events_;
  // Answers (non-frame, non-ack lines) waiting for Command()/the open sequence.
  std::deque<slcan::Message> replies_;
  bool channel_open_ = false;  // the open sequence succeeded: close the channel at the end
};

/// Opens a serial device or pty in raw mode (8N1, no flow control, `uart_baud` for real UARTs;
/// ignored by ptys and USB CDC) and returns an SlcanTransport on it. Fails (kCommunication) when
/// the path does not exist, is not a terminal, or the adapter refuses.
Expected<std::unique_ptr<SlcanTransport>> OpenSlcanSerial(const std::string& device,
                                                          const SlcanOptions& options,
                                                          uint32_t uart_baud = 115200);
/// Connects to HOST:PORT (TCP_NODELAY) and returns an SlcanTransport on the socket. Fails
/// (kCommunication) when the name does not resolve or the connection is refused / times out
/// (`connect_timeout`).
Expected<std::unique_ptr<SlcanTransport>> OpenSlcanTcp(
    const std::string& host,
    uint16_t port,
    const SlcanOptions& options,
    std::chrono::milliseconds connect_timeout = std::chrono::milliseconds(3000));

}  // namespace volcomp::can_io
