// SlcanServer: SLCAN device emulation on a pty or a TCP socket.
#include "volcomp/can_io/slcan_server.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "fd_io.hpp"
#include "volcomp/can/slcan.hpp"

namespace volcomp::can_io {

using Clock = std::chrono::steady_clock;
using detail::UniqueFd;

struct SlcanServer::Impl {
  SlcanServerOptions options;
  bool is_pty = false;
  UniqueFd master;  // pty: our side
  UniqueFd slave;   // pty: kept open so the master never sees a hangup between clients
  std::string slave_path;
  UniqueFd listener;  // tcp
  UniqueFd client;    // tcp
  std::string address;
  uint16_t port = 0;

  slcan::Decoder decoder{slcan::Role::kDevice};
  std::string out;  // bytes waiting for the client
  std::vector<CanFrame> received;
  bool open = false;
  bool listen_only = false;
  bool timestamps = false;
  bool overrun = false;  // frames dropped since the last F (status bit 3)
  uint32_t bitrate = 0;
  Clock::time_point origin = Clock::now();
  SlcanServerStats stats;

  ~Impl() {
    if (!options.symlink.empty()) ::unlink(options.symlink.c_str());
  }

  int io_fd() const { return is_pty ? master.get() : client.get(); }

  void ResetSession() {
    open = false;
    listen_only = false;
    timestamps = false;
    overrun = false;  // the bitrate stays, as on an adapter
    decoder.Reset();
    out.clear();
  }

  void Reply(const char* text) { out += text; }
  void Ack() { out += '\r'; }
  void Bel() {
    out += '\a';
    ++stats.errors_answered;
  }
  void ReplyText(char letter, const std::string& text) {
    out += letter;
    out += text;
    out += '\r';
  }

  void Handle(const slcan::Message& m) {
    using slcan::Kind;
    switch (m.kind) {
      case Kind::kFrame:
        if (!open || listen_only) return Bel();
        received.push_back(m.frame);
        ++stats.frames_from_client;
        if (options.cr_tx_ack) return Ack();
        return Reply(m.frame.extended ? "Z\r" : "z\r");
      case Kind::kOpen:
      case Kind::kListenOnly:
        if (!open) origin = Clock::now();
        open = true;  // a second O (python-can sends two) is simply acknowledged
        listen_only = m.kind == Kind::kListenOnly;
        return Ack();
      case Kind::kClose:
        if (open && is_pty) {
          // A new session starts with C: drop what the previous client left unread.
          out.clear();
          ::tcflush(slave.get(), TCIFLUSH);
        }
        open = false;
        listen_only = false;
        return Ack();
      case Kind::kBitrate:
        bitrate = slcan::BitrateForIndex(m.value);
        return Ack();
      case Kind::kBtr:
      case Kind::kAcceptCode:
      case Kind::kAcceptMask:
      case Kind::kUartRate:
        return Ack();
      case Kind::kTimestamps:
        timestamps = m.value != 0;
        return Ack();
      case Kind::kAutoPoll:
        return m.value != 0 ? Ack() : Bel();  // always auto-polling
      case Kind::kStatusRequest: {
        char line[8];
        std::snprintf(line, sizeof line, "F%02X\r", overrun ? 0x08u : 0x00u);
        overrun = false;
        return Reply(line);
      }
      case Kind::kVersionRequest:
        return ReplyText('V', options.version);
      case Kind::kDetailRequest:
        return ReplyText('v', options.detail);
      case Kind::kSerialRequest:
        return ReplyText('N', options.serial);
      default:
        return Bel();  // P, A, malformed, unknown
    }
  }

  void Send(const CanFrame& frame) {
    if (!open || io_fd() < 0) {
      ++stats.frames_dropped;
      return;
    }
    slcan::Message m;
    m.kind = slcan::Kind::kFrame;
    m.frame = frame;
    if (timestamps) {
      const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - origin);
      m.has_timestamp = true;
      m.timestamp_ms = static_cast<uint16_t>(ms.count() % 60000);
    }
    char line[slcan::kMaxEncodedLength];
    const size_t n = slcan::Encode(m, line, sizeof line);
    if (n == 0 || out.size() + n > options.max_backlog) {
      ++stats.frames_dropped;
      overrun = true;
      return;
    }
    out.append(line, n);
    ++stats.frames_to_client;
  }

  void DropClient() {
    client.Reset();
    ResetSession();
  }

  void Flush() {
    const int fd = io_fd();
    if (fd < 0) {
      out.clear();
      return;
    }
    size_t done = 0;
    while (done < out.size()) {
      const ssize_t n = is_pty ? ::write(fd, out.data() + done, out.size() - done)
                               : ::send(fd, out.data() + done, out.size() - done, MSG_NOSIGNAL);
      if (n > 0) {
        done += static_cast<size_t>(n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (!is_pty) return DropClient();  // peer gone
      break;
    }
    out.erase(0, done);
  }

  void Read() {
    char buf[4096];
    for (;;) {
      const int fd = io_fd();
      if (fd < 0) return;
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n > 0) {
        for (ssize_t i = 0; i < n; ++i) {
          slcan::Message m;
          if (decoder.Feed(static_cast<uint8_t>(buf[i]), &m)) Handle(m);
        }
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
      if (!is_pty) DropClient();  // EOF or reset
      return;
    }
  }

  void Accept() {
    const int fd = ::accept4(listener.get(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    client.Reset(fd);
    ResetSession();
    ++stats.clients;
  }
};

SlcanServer::SlcanServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SlcanServer::~SlcanServer() = default;

Expected<std::unique_ptr<SlcanServer>> SlcanServer::CreatePty(const SlcanServerOptions& options) {
  auto impl = std::make_unique<Impl>();
  impl->is_pty = true;
  int master = -1;
  int slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    return Fail(Error::kIoError, "slcan server: openpty failed: " + detail::ErrnoText(errno));
  }
  impl->master.Reset(master);
  impl->slave.Reset(slave);
  ::fcntl(master, F_SETFD, FD_CLOEXEC);
  ::fcntl(slave, F_SETFD, FD_CLOEXEC);
  termios tio{};
  if (::tcgetattr(slave, &tio) != 0) {
    return Fail(Error::kIoError, "slcan server: tcgetattr on pty: " + detail::ErrnoText(errno));
  }
  ::cfmakeraw(&tio);
  ::tcsetattr(slave, TCSANOW, &tio);
  VOLCOMP_TRY(detail::SetNonBlocking(master, "slcan server pty"));
  char name[128] = {};
  if (::ttyname_r(slave, name, sizeof name) != 0) {
    return Fail(Error::kIoError, "slcan server: cannot name the pty: " + detail::ErrnoText(errno));
  }
  impl->slave_path = name;
  if (!options.symlink.empty()) {
    struct stat st {};
    if (::lstat(options.symlink.c_str(), &st) == 0) {
      if (!S_ISLNK(st.st_mode)) {
        return Fail(Error::kIoError, "slcan server: '" + options.symlink +
                                         "' exists and is not a symlink; not replacing it");
      }
      ::unlink(options.symlink.c_str());
    }
    if (::symlink(name, options.symlink.c_str()) != 0) {
      return Fail(Error::kIoError, "slcan server: cannot create symlink '" + options.symlink +
                                       "': " + detail::ErrnoText(errno));
    }
  }
  impl->options = options;  // after the symlink exists: ~Impl removes it
  return std::unique_ptr<SlcanServer>(new SlcanServer(std::move(impl)));
}

Expected<std::unique_ptr<SlcanServer>> SlcanServer::CreateTcp(const std::string& address,
                                                              uint16_t port,
                                                              const SlcanServerOptions& options) {
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->options.symlink.clear();
  const std::string what = "slcan server " + address + ":" + std::to_string(port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* list = nullptr;
  const int gai = ::getaddrinfo(address.empty() ? nullptr : address.c_str(),
                                std::to_string(port).c_str(), &hints, &list);
  if (gai != 0) return Fail(Error::kIoError, what + ": " + ::gai_strerror(gai));
  std::string error = "no address";
  for (addrinfo* a = list; a != nullptr && !impl->listener.valid(); a = a->ai_next) {
    UniqueFd fd(::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    if (!fd.valid()) continue;
    const int one = 1;
    ::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd.get(), a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd.get(), 4) != 0) {
      error = detail::ErrnoText(errno);
      continue;
    }
    impl->listener = std::move(fd);
  }
  ::freeaddrinfo(list);
  if (!impl->listener.valid()) return Fail(Error::kIoError, what + ": cannot listen: " + error);
  sockaddr_storage bound{};
  socklen_t len = sizeof bound;
  ::getsockname(impl->listener.get(), reinterpret_cast<sockaddr*>(&bound), &len);
  impl->port = bound.ss_family == AF_INET6
                   ? ntohs(reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port)
                   : ntohs(reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
  impl->address = address.empty() ? "0.0.0.0" : address;
  return std::unique_ptr<SlcanServer>(new SlcanServer(std::move(impl)));
}

std::string SlcanServer::endpoint() const {
  if (impl_->is_pty) return impl_->slave_path;
  const bool v6 = impl_->address.find(':') != std::string::npos;
  return (v6 ? "[" + impl_->address + "]" : impl_->address) + ":" + std::to_string(impl_->port);
}

std::string SlcanServer::client_spec() const {
  return (impl_->is_pty ? "slcan:" : "slcan-tcp:") + endpoint();
}

uint16_t SlcanServer::port() const { return impl_->port; }

Expected<bool> SlcanServer::Poll(std::chrono::microseconds timeout) {
  Impl& s = *impl_;
  s.Flush();
  pollfd fds[2];
  nfds_t count = 0;
  const int io = s.io_fd();
  if (io >= 0) {
    fds[count++] = {io, static_cast<short>(POLLIN | (s.out.empty() ? 0 : POLLOUT)), 0};
  } else if (s.listener.valid()) {
    fds[count++] = {s.listener.get(), POLLIN, 0};
  }
  if (s.received.empty() && count > 0) {
    if (detail::PollFds(fds, count, timeout) < 0) {
      return Fail(Error::kIoError, "slcan server: poll failed: " + detail::ErrnoText(errno));
    }
  }
  if (io < 0 && s.listener.valid()) {
    s.Accept();
  } else if (io >= 0) {
    s.Read();
  }
  s.Flush();
  return !s.received.empty();
}

std::vector<CanFrame> SlcanServer::TakeReceived() {
  std::vector<CanFrame> out;
  out.swap(impl_->received);
  return out;
}

void SlcanServer::Send(const CanFrame& frame) { impl_->Send(frame); }
bool SlcanServer::client_connected() const { return impl_->is_pty || impl_->client.valid(); }
bool SlcanServer::channel_open() const { return impl_->open; }
bool SlcanServer::listen_only() const { return impl_->listen_only; }
uint32_t SlcanServer::bitrate() const { return impl_->bitrate; }
const SlcanServerStats& SlcanServer::stats() const { return impl_->stats; }

}  // namespace volcomp::can_io
