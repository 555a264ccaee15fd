// File-descriptor helpers shared by the can_io sources (private header).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "volcomp/hosted/expected.hpp"

struct pollfd;

namespace volcomp::can_io::detail {

/// Owns a file descriptor; closes it on destruction.
class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  ~UniqueFd() { Reset(); }
  UniqueFd(UniqueFd&& o) noexcept : fd_(o.Release()) {}
  UniqueFd& operator=(UniqueFd&& o) noexcept {
    if (this != &o) Reset(o.Release());
    return *this;
  }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;

  int get() const { return fd_; }
  bool valid() const { return fd_ >= 0; }
  int Release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }
  void Reset(int fd = -1);

 private:
  int fd_ = -1;
};

/// ppoll() with microsecond resolution (poll()'s milliseconds would stretch the short waits of a
/// bus paced to real time); returns ppoll's result, EINTR retried with the time left.
int PollFds(struct pollfd* fds, unsigned long count, std::chrono::microseconds timeout);
/// One fd; returns revents (0 on timeout). Negative timeouts mean 0.
short PollFd(int fd, short events, std::chrono::microseconds timeout);
/// Sets O_NONBLOCK; a failure (kIoError) names `what`.
Outcome SetNonBlocking(int fd, const std::string& what);
/// Writes all bytes to a non-blocking fd, waiting for POLLOUT up to `timeout` in total; an error
/// or the timeout is a kCommunication failure "<what>: ...".
Outcome WriteAll(int fd,
                 const char* data,
                 size_t size,
                 std::chrono::milliseconds timeout,
                 const std::string& what);
/// strerror(err) as a std::string.
std::string ErrnoText(int err);

}  // namespace volcomp::can_io::detail
