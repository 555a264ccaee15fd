// timerfd periodic tick.
#include "volcomp/hal/linux/tick_timer.hpp"

#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace volcomp::hal::linux_board {

std::string TickTimer::Start(uint64_t period_ns) {
  Close();
  if (period_ns < 1000) return "tick period below 1 us";
  fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
  if (fd_ < 0) return std::string("timerfd_create: ") + std::strerror(errno);
  itimerspec spec{};
  spec.it_interval.tv_sec = static_cast<time_t>(period_ns / 1000000000u);
  spec.it_interval.tv_nsec = static_cast<long>(period_ns % 1000000000u);
  spec.it_value = spec.it_interval;  // first expiry one period from now
  if (timerfd_settime(fd_, 0, &spec, nullptr) != 0) {
    const std::string why = std::string("timerfd_settime: ") + std::strerror(errno);
    Close();
    return why;
  }
  period_ns_ = period_ns;
  return "";
}

void TickTimer::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

uint64_t TickTimer::Take() {
  if (fd_ < 0) return 0;
  uint64_t n = 0;
  const ssize_t r = ::read(fd_, &n, sizeof n);
  return r == static_cast<ssize_t>(sizeof n) ? n : 0;
}

}  // namespace volcomp::hal::linux_board
