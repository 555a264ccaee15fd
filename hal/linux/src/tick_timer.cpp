// timerfd periodic tick.
#include "volcomp/hal/linux/tick_timer.hpp"

#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace volcomp::hal::linux_board {

Expected<void> TickTimer::Open() {
  Close();
  fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
  if (fd_ < 0) return Fail(Error::kIoError, std::string("timerfd_create: ") + std::strerror(errno));
  return Expected<void>::Ok();
}

void TickTimer::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  running_ = false;
}

Status TickTimer::DoSetRate(uint32_t tick_hz) {
  if (fd_ < 0) return Error::kNotReady;
  if (running_) return Error::kBusy;
  const uint64_t period_ns = 1000000000ull / tick_hz;
  if (period_ns < 1000) return Error::kConfigInvalid;
  rate_hz_ = tick_hz;
  period_ns_ = period_ns;
  return Status::Ok();
}

Status TickTimer::DoStart() {
  if (fd_ < 0 || period_ns_ == 0) return Error::kNotReady;
  itimerspec spec{};
  spec.it_interval.tv_sec = static_cast<time_t>(period_ns_ / 1000000000u);
  spec.it_interval.tv_nsec = static_cast<long>(period_ns_ % 1000000000u);
  spec.it_value = spec.it_interval;  // first expiry one period from now
  if (timerfd_settime(fd_, 0, &spec, nullptr) != 0) return Error::kIoError;
  running_ = true;
  ++starts_;
  return Status::Ok();
}

void TickTimer::DoStop() {
  if (fd_ < 0) return;
  const itimerspec off{};
  timerfd_settime(fd_, 0, &off, nullptr);  // disarms; the expiration count restarts at 0
  running_ = false;
}

uint64_t TickTimer::Take() {
  if (fd_ < 0) return 0;
  uint64_t n = 0;
  const ssize_t r = ::read(fd_, &n, sizeof n);
  return r == static_cast<ssize_t>(sizeof n) ? n : 0;
}

}  // namespace volcomp::hal::linux_board
