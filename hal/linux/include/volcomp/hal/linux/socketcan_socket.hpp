// A Linux SocketCAN raw socket (CAN_RAW, classic frames), the one SocketCAN implementation of the
// firmware's port (SocketCanPort) and the PC tool's transport. Never throws: failures are Expected
// (code and message) or IoResult + errno. Non-blocking (wait with poll() on fd()); error frames on
// by default, decoded into CanErrorInfo. Threading: one thread per object.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::hal::socketcan {

/// A receive filter: a frame passes when (frame.id & mask) == (id & mask) and its format matches
/// `extended` (the kernel's can_filter with CAN_EFF_FLAG in id and mask).
struct CanFilter {
  uint32_t id = 0;
  uint32_t mask = 0;
  bool extended = false;
};

/// Controller state as reported by error frames, in increasing severity.
enum class BusState : uint8_t { kErrorActive, kErrorWarning, kErrorPassive, kBusOff };

const char* BusStateName(BusState state);

/// One decoded error frame (linux/can/error.h classes). `state` is the state the frame announces,
/// or `state_changed` false when it announces none.
struct CanErrorInfo {
  bool state_changed = false;
  BusState state = BusState::kErrorActive;
  bool bus_off = false;     // CAN_ERR_BUSOFF
  bool restarted = false;   // CAN_ERR_RESTARTED: controller left bus-off
  bool tx_timeout = false;  // CAN_ERR_TX_TIMEOUT
  bool lost_arbitration = false;
  bool no_ack = false;          // CAN_ERR_ACK: nobody acknowledged our frame
  bool bus_error = false;       // CAN_ERR_BUSERROR
  bool protocol_error = false;  // CAN_ERR_PROT (bit, form, stuff ... error; data[2..3])
  bool rx_overflow = false;     // controller receive overflow (frames lost)
  bool tx_overflow = false;
  bool has_counters = false;  // CAN_ERR_CNT
  uint8_t tx_errors = 0;
  uint8_t rx_errors = 0;
  uint32_t raw_class = 0;  // error class bits of can_id
};

/// Decodes an error frame's can_id (with or without CAN_ERR_FLAG) and 8 data bytes. Pure.
CanErrorInfo DecodeErrorFrame(uint32_t can_id, const uint8_t data[8]);
/// One line describing an error frame, e.g. "bus-off; tx errors 255 rx errors 0".
std::string DescribeError(const CanErrorInfo& info);

class SocketCanSocket {
 public:
  struct Options {
    std::vector<CanFilter> filters;  // empty: receive everything
    bool error_frames = true;        // subscribe to every error class
    bool receive_own = false;        // CAN_RAW_RECV_OWN_MSGS
    // Receive buffer to ask for (SO_RCVBUFFORCE where permitted, else SO_RCVBUF, which the kernel
    // caps at net.core.rmem_max); 0 keeps the kernel's default (net.core.rmem_default, room for
    // a few hundred frames). Not getting it is not an error: receive_buffer_bytes() says what
    // the socket has.
    uint32_t receive_buffer_bytes = 0;
  };
  enum class IoResult : uint8_t {
    kOk,          // one frame written / read
    kWouldBlock,  // EAGAIN; on write also ENOBUFS (the interface queue is full: pace and retry)
    kError,       // see *err (errno)
  };

  SocketCanSocket() = default;
  ~SocketCanSocket() { Close(); }
  SocketCanSocket(SocketCanSocket&& other) noexcept;
  SocketCanSocket& operator=(SocketCanSocket&& other) noexcept;
  SocketCanSocket(const SocketCanSocket&) = delete;
  SocketCanSocket& operator=(const SocketCanSocket&) = delete;

  /// Opens a non-blocking CAN_RAW socket bound to `iface`. A failure's message names the cause,
  /// e.g. "socketcan: address family not supported: this kernel has no CAN support (...)" or
  /// "socketcan: no such interface 'can9'" (kInvalidArgument for a bad name, else kIoError).
  Expected<void> Open(const std::string& iface, const Options& options);
  void Close();
  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  const std::string& iface() const { return iface_; }

  /// Writes one frame without blocking.
  IoResult Write(const CanFrame& frame, int* err);
  /// Reads one frame without blocking. Data/remote frames fill *frame and set *is_error false;
  /// error frames fill *error and set *is_error true.
  IoResult Read(CanFrame* frame, CanErrorInfo* error, bool* is_error, int* err);

  /// Frames the kernel dropped for this socket since Open() because its receive buffer was full
  /// (SO_RXQ_OVFL). The kernel reports the count with the next frame it queues after the drops,
  /// so it is known once that frame has been read.
  uint32_t dropped_frames() const { return dropped_; }
  /// The socket's receive buffer as the kernel reports it (SO_RCVBUF; it counts its own overhead,
  /// several hundred bytes per frame).
  uint32_t receive_buffer_bytes() const;

  /// poll() for readability / writability; false on timeout.
  bool WaitReadable(std::chrono::microseconds timeout) const;
  bool WaitWritable(std::chrono::microseconds timeout) const;

 private:
  int fd_ = -1;
  std::string iface_;
  uint32_t dropped_ = 0;
};

/// Asks the kernel to restart a bus-off CAN controller now (rtnetlink, IFLA_CAN_RESTART; what
/// `ip link set IFACE type can restart` does). Needs CAP_NET_ADMIN; fails on virtual interfaces
/// (vcan) and on controllers that are not bus-off.
Expected<void> RequestCanRestart(const std::string& iface);

/// The bit rate (bit/s) the kernel runs a CAN interface at (rtnetlink RTM_GETLINK,
/// IFLA_CAN_BITTIMING; unprivileged). An unprivileged process cannot set it (`ip link set IFACE
/// type can bitrate N` needs CAP_NET_ADMIN), only compare it. kNotFound when the interface does
/// not exist or reports no bit timing (virtual interfaces: vcan, vxcan); kIoError when the query
/// fails.
Expected<uint32_t> ReadCanBitrate(const std::string& iface);
/// The bit rate in a kernel answer to RTM_GETLINK (`size` bytes of netlink messages): kNotFound
/// when it carries none (or 0), kIoError for a netlink error message. Pure.
Expected<uint32_t> ParseLinkBitrate(const uint8_t* message, size_t size);

/// "socketcan: <what>: <strerror>" with hints for the common errno values.
std::string SocketCanErrorText(const std::string& what, int err);

}  // namespace volcomp::hal::socketcan
