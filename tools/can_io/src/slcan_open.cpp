// Opening SLCAN links: raw serial devices / ptys and TCP connections.
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

#include "fd_io.hpp"
#include "volcomp/can_io/slcan_transport.hpp"

namespace volcomp::can_io {
namespace {

speed_t BaudConstant(uint32_t baud) {
  switch (baud) {
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 500000:
      return B500000;
    case 921600:
      return B921600;
    case 1000000:
      return B1000000;
    case 2000000:
      return B2000000;
    case 3000000:
      return B3000000;
    default:
      return B0;
  }
}

}  // namespace

Expected<std::unique_ptr<SlcanTransport>> OpenSlcanSerial(const std::string& device,
                                                          const SlcanOptions& options,
                                                          uint32_t uart_baud) {
  const std::string what = "slcan:" + device;
  const speed_t speed = BaudConstant(uart_baud);
  if (speed == B0) {
    return Fail(Error::kInvalidArgument,
                what + ": unsupported UART baud rate " + std::to_string(uart_baud));
  }
  detail::UniqueFd fd(::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd.valid()) {
    const int err = errno;
    return Fail(Error::kCommunication,
                what + ": cannot open: " + detail::ErrnoText(err) +
                    (err == EACCES ? " (add yourself to the dialout group?)" : ""));
  }
  termios tio{};
  if (::tcgetattr(fd.get(), &tio) != 0) {
    return Fail(Error::kCommunication,
                what + ": not a serial device or pty (" + detail::ErrnoText(errno) + ")");
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS | CSTOPB);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, speed);
  ::cfsetospeed(&tio, speed);
  if (::tcsetattr(fd.get(), TCSANOW, &tio) != 0) {
    return Fail(Error::kCommunication, what + ": cannot set raw mode: " + detail::ErrnoText(errno));
  }
  ::tcflush(fd.get(), TCIOFLUSH);  // stale bytes from an earlier session
  return SlcanTransport::Open(fd.Release(), what, options);
}

Expected<std::unique_ptr<SlcanTransport>> OpenSlcanTcp(const std::string& host,
                                                       uint16_t port,
                                                       const SlcanOptions& options,
                                                       std::chrono::milliseconds connect_timeout) {
  const std::string what = "slcan-tcp:" + host + ":" + std::to_string(port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* list = nullptr;
  const int gai = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &list);
  if (gai != 0) {
    return Fail(Error::kCommunication,
                what + ": cannot resolve '" + host + "': " + ::gai_strerror(gai));
  }
  std::string last_error = "no address";
  detail::UniqueFd connected;
  for (addrinfo* a = list; a != nullptr && !connected.valid(); a = a->ai_next) {
    detail::UniqueFd fd(
        ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol));
    if (!fd.valid()) {
      last_error = detail::ErrnoText(errno);
      continue;
    }
    int err = 0;
    if (::connect(fd.get(), a->ai_addr, a->ai_addrlen) != 0) {
      err = errno;
      if (err == EINPROGRESS) {
        const short ev =
            detail::PollFd(fd.get(), POLLOUT,
                           std::chrono::duration_cast<std::chrono::microseconds>(connect_timeout));
        if (ev == 0) {
          last_error =
              "connection timed out after " + std::to_string(connect_timeout.count()) + " ms";
          continue;
        }
        socklen_t len = sizeof err;
        ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &err, &len);
      }
    }
    if (err != 0) {
      last_error = detail::ErrnoText(err);
      continue;
    }
    const int one = 1;
    ::setsockopt(fd.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    connected = std::move(fd);
  }
  ::freeaddrinfo(list);
  if (!connected.valid()) {
    return Fail(Error::kCommunication, what + ": cannot connect: " + last_error +
                                           " (is the simulator or slcan server running?)");
  }
  return SlcanTransport::Open(connected.Release(), what, options);
}

}  // namespace volcomp::can_io
