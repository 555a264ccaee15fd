// File-descriptor helpers.
#include "fd_io.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace volcomp::can_io::detail {

void UniqueFd::Reset(int fd) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
}

int PollFds(pollfd* fds, unsigned long count, std::chrono::microseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto left = std::chrono::duration_cast<std::chrono::microseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() < 0) left = std::chrono::microseconds(0);
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(left.count() / 1000000);
    ts.tv_nsec = static_cast<long>(left.count() % 1000000) * 1000;
    const int r = ::ppoll(fds, count, &ts, nullptr);
    if (r >= 0 || errno != EINTR) return r;
  }
}

short PollFd(int fd, short events, std::chrono::microseconds timeout) {
  pollfd p{fd, events, 0};
  const int r = PollFds(&p, 1, timeout);
  if (r > 0) return p.revents;
  return r == 0 ? 0 : POLLERR;
}

Outcome SetNonBlocking(int fd, const std::string& what) {
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) < 0) {
    return Fail(Error::kIoError, what + ": cannot set non-blocking mode: " + ErrnoText(errno));
  }
  return Outcome::Ok();
}

Outcome WriteAll(int fd,
                 const char* data,
                 size_t size,
                 std::chrono::milliseconds timeout,
                 const std::string& what) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  bool is_socket = true;  // send(MSG_NOSIGNAL): a closed TCP peer gives EPIPE, not SIGPIPE
  while (size > 0) {
    ssize_t n = is_socket ? ::send(fd, data, size, MSG_NOSIGNAL) : ::write(fd, data, size);
    if (n < 0 && errno == ENOTSOCK) {
      is_socket = false;
      continue;
    }
    if (n > 0) {
      data += n;
      size -= static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      return Fail(Error::kCommunication, what + ": write failed: " + ErrnoText(errno));
    }
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      return Fail(Error::kCommunication, what + ": write timed out (peer not reading for " +
                                             std::to_string(timeout.count()) + " ms)");
    }
    const short ev = PollFd(fd, POLLOUT, left);
    if ((ev & (POLLERR | POLLNVAL)) != 0) {
      return Fail(Error::kCommunication, what + ": write failed: connection error");
    }
  }
  return Outcome::Ok();
}

std::string ErrnoText(int err) { return std::strerror(err); }

}  // namespace volcomp::can_io::detail
