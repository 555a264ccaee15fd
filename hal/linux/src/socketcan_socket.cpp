// SocketCAN raw socket: open/bind/filters, frame I/O, error-frame decoding.
#include "volcomp/hal/linux/socketcan_socket.hpp"

#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace volcomp::hal::socketcan {
namespace {

int PollOne(int fd, short events, std::chrono::microseconds timeout) {
  pollfd p{fd, events, 0};
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
      timeout + std::chrono::microseconds(999));
  const int r = ::poll(&p, 1, timeout.count() <= 0 ? 0 : static_cast<int>(ms.count()));
  return r > 0 ? p.revents : 0;
}

}  // namespace

const char* BusStateName(BusState state) {
  switch (state) {
    case BusState::kErrorActive:
      return "error-active";
    case BusState::kErrorWarning:
      return "error-warning";
    case BusState::kErrorPassive:
      return "error-passive";
    case BusState::kBusOff:
      return "bus-off";
  }
  return "unknown";
}

CanErrorInfo DecodeErrorFrame(uint32_t can_id, const uint8_t data[8]) {
  CanErrorInfo info;
  const uint32_t cls = can_id & CAN_ERR_MASK;
  info.raw_class = cls;
  info.tx_timeout = (cls & CAN_ERR_TX_TIMEOUT) != 0;
  info.lost_arbitration = (cls & CAN_ERR_LOSTARB) != 0;
  info.protocol_error = (cls & CAN_ERR_PROT) != 0;
  info.no_ack = (cls & CAN_ERR_ACK) != 0;
  info.bus_error = (cls & CAN_ERR_BUSERROR) != 0;
  info.restarted = (cls & CAN_ERR_RESTARTED) != 0;
  info.bus_off = (cls & CAN_ERR_BUSOFF) != 0;
  if ((cls & CAN_ERR_CRTL) != 0) {
    const uint8_t c = data[1];
    info.rx_overflow = (c & CAN_ERR_CRTL_RX_OVERFLOW) != 0;
    info.tx_overflow = (c & CAN_ERR_CRTL_TX_OVERFLOW) != 0;
    if ((c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0) {
      info.state_changed = true;
      info.state = BusState::kErrorPassive;
    } else if ((c & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) != 0) {
      info.state_changed = true;
      info.state = BusState::kErrorWarning;
    } else if ((c & CAN_ERR_CRTL_ACTIVE) != 0) {
      info.state_changed = true;
      info.state = BusState::kErrorActive;
    }
  }
  if (info.restarted) {
    info.state_changed = true;
    info.state = BusState::kErrorActive;
  }
  if (info.bus_off) {  // most severe wins
    info.state_changed = true;
    info.state = BusState::kBusOff;
  }
  if ((cls & CAN_ERR_CNT) != 0) {
    info.has_counters = true;
    info.tx_errors = data[6];
    info.rx_errors = data[7];
  }
  return info;
}

std::string DescribeError(const CanErrorInfo& info) {
  std::string s;
  auto add = [&s](const char* what) {
    if (!s.empty()) s += ", ";
    s += what;
  };
  if (info.state_changed) add(BusStateName(info.state));
  if (info.restarted) add("controller restarted");
  if (info.tx_timeout) add("tx timeout");
  if (info.lost_arbitration) add("lost arbitration");
  if (info.no_ack) add("no ack");
  if (info.protocol_error) add("protocol violation");
  if (info.bus_error) add("bus error");
  if (info.rx_overflow) add("rx overflow");
  if (info.tx_overflow) add("tx overflow");
  if (info.has_counters) {
    add(("tx errors " + std::to_string(info.tx_errors) + " rx errors " +
         std::to_string(info.rx_errors))
            .c_str());
  }
  if (s.empty()) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "error frame (class 0x%03X)",
                  static_cast<unsigned>(info.raw_class));
    s = buf;
  }
  return s;
}

std::string SocketCanErrorText(const std::string& what, int err) {
  std::string s = "socketcan: " + what + ": ";
  switch (err) {
    case EAFNOSUPPORT:
      return s +
             "address family not supported: this kernel has no CAN support (try "
             "slcan-tcp:HOST:PORT against a simulator, or run inside user-mode-linux)";
    case ENODEV:
      return s + "no such interface (list them with `ip link`)";
    case ENETDOWN:
      return s + "interface is down (ip link set IFACE up)";
    case EPERM:
    case EACCES:
      return s + std::strerror(err) + " (needs CAP_NET_ADMIN / root)";
    default:
      return s + std::strerror(err);
  }
}

SocketCanSocket::SocketCanSocket(SocketCanSocket&& other) noexcept
    : fd_(other.fd_), iface_(std::move(other.iface_)), dropped_(other.dropped_) {
  other.fd_ = -1;
}

SocketCanSocket& SocketCanSocket::operator=(SocketCanSocket&& other) noexcept {
  if (this != &other) {
    Close();
    fd_ = other.fd_;
    iface_ = std::move(other.iface_);
    dropped_ = other.dropped_;
    other.fd_ = -1;
  }
  return *this;
}

void SocketCanSocket::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

Expected<void> SocketCanSocket::Open(const std::string& iface, const Options& options) {
  Close();
  if (iface.empty() || iface.size() >= IFNAMSIZ) {
    return Fail(Error::kInvalidArgument, "socketcan: bad interface name '" + iface + "' (1.." +
                                             std::to_string(IFNAMSIZ - 1) + " characters)");
  }
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return Fail(Error::kIoError, SocketCanErrorText("socket(AF_CAN)", errno));
  auto fail = [fd](const std::string& what) {
    const int err = errno;
    ::close(fd);
    return Fail(Error::kIoError, SocketCanErrorText(what, err));
  };
  const unsigned index = ::if_nametoindex(iface.c_str());
  if (index == 0) return fail("interface '" + iface + "'");
  if (!options.filters.empty()) {
    std::vector<can_filter> filters;
    for (const CanFilter& f : options.filters) {
      can_filter k{};
      const canid_t flag = f.extended ? CAN_EFF_FLAG : 0;
      k.can_id = (f.id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK)) | flag;
      k.can_mask = (f.mask & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK)) | CAN_EFF_FLAG;
      filters.push_back(k);
    }
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, filters.data(),
                     static_cast<socklen_t>(filters.size() * sizeof(can_filter))) != 0) {
      return fail("setsockopt(CAN_RAW_FILTER)");
    }
  }
  if (options.error_frames) {
    const can_err_mask_t mask = CAN_ERR_MASK;
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &mask, sizeof mask) != 0) {
      return fail("setsockopt(CAN_RAW_ERR_FILTER)");
    }
  }
  if (options.receive_own) {
    const int on = 1;
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &on, sizeof on) != 0) {
      return fail("setsockopt(CAN_RAW_RECV_OWN_MSGS)");
    }
  }
  // The kernel's count of frames it dropped for this socket, with every frame read (Read()).
  const int on = 1;
  if (::setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on) != 0) {
    return fail("setsockopt(SO_RXQ_OVFL)");
  }
  if (options.receive_buffer_bytes != 0) {
    const int bytes = static_cast<int>(options.receive_buffer_bytes);
    if (::setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &bytes, sizeof bytes) != 0) {
      ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof bytes);  // capped: still more room
    }
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(index);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    return fail("bind to '" + iface + "'");
  }
  fd_ = fd;
  iface_ = iface;
  dropped_ = 0;
  return Expected<void>::Ok();
}

SocketCanSocket::IoResult SocketCanSocket::Write(const CanFrame& frame, int* err) {
  can_frame cf{};
  cf.can_id = frame.id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (frame.extended) cf.can_id |= CAN_EFF_FLAG;
  if (frame.rtr) cf.can_id |= CAN_RTR_FLAG;
  cf.can_dlc = frame.dlc > 8 ? 8 : frame.dlc;
  if (!frame.rtr) std::memcpy(cf.data, frame.data, cf.can_dlc);
  const ssize_t n = ::write(fd_, &cf, sizeof cf);
  if (n == static_cast<ssize_t>(sizeof cf)) return IoResult::kOk;
  const int e = n < 0 ? errno : EIO;
  if (e == EAGAIN || e == EWOULDBLOCK || e == ENOBUFS) return IoResult::kWouldBlock;
  if (err != nullptr) *err = e;
  return IoResult::kError;
}

SocketCanSocket::IoResult SocketCanSocket::Read(CanFrame* frame,
                                                CanErrorInfo* error,
                                                bool* is_error,
                                                int* err) {
  can_frame cf{};
  iovec iov{&cf, sizeof cf};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(uint32_t))];
  msghdr msg{};
  msg.msg_iov = &iov;
  msg.msg_iovlen = 1;
  msg.msg_control = control;
  msg.msg_controllen = sizeof control;
  const ssize_t n = ::recvmsg(fd_, &msg, 0);
  if (n >= 0) {
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
        std::memcpy(&dropped_, CMSG_DATA(c), sizeof dropped_);
      }
    }
  }
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK) return IoResult::kWouldBlock;
    if (err != nullptr) *err = errno;
    return IoResult::kError;
  }
  if (n != static_cast<ssize_t>(sizeof cf)) {  // CAN FD frames are never enabled here
    if (err != nullptr) *err = EIO;
    return IoResult::kError;
  }
  if ((cf.can_id & CAN_ERR_FLAG) != 0) {
    *is_error = true;
    *error = DecodeErrorFrame(cf.can_id, cf.data);
    return IoResult::kOk;
  }
  *is_error = false;
  CanFrame f;
  f.extended = (cf.can_id & CAN_EFF_FLAG) != 0;
  f.rtr = (cf.can_id & CAN_RTR_FLAG) != 0;
  f.id = cf.can_id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  f.dlc = cf.can_dlc > 8 ? 8 : cf.can_dlc;
  if (!f.rtr) std::memcpy(f.data, cf.data, f.dlc);
  *frame = f;
  return IoResult::kOk;
}

uint32_t SocketCanSocket::receive_buffer_bytes() const {
  int bytes = 0;
  socklen_t len = sizeof bytes;
  if (fd_ < 0 || ::getsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &bytes, &len) != 0) return 0;
  return static_cast<uint32_t>(bytes);
}

bool SocketCanSocket::WaitReadable(std::chrono::microseconds timeout) const {
  return (PollOne(fd_, POLLIN, timeout) & (POLLIN | POLLERR | POLLHUP)) != 0;
}

bool SocketCanSocket::WaitWritable(std::chrono::microseconds timeout) const {
  return (PollOne(fd_, POLLOUT, timeout) & (POLLOUT | POLLERR | POLLHUP)) != 0;
}

}  // namespace volcomp::hal::socketcan
