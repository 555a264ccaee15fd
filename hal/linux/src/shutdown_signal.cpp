// signalfd for SIGINT / SIGTERM / SIGHUP.
#include "volcomp/hal/linux/shutdown_signal.hpp"

#include <sys/signalfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace volcomp::hal::linux_board {

Expected<void> ShutdownSignal::Open() {
  Close();
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  if (pthread_sigmask(SIG_BLOCK, &set, &old_mask_) != 0) {
    return Fail(Error::kIoError, "pthread_sigmask failed");
  }
  mask_saved_ = true;
  fd_ = signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC);
  if (fd_ < 0) {
    const std::string why = std::string("signalfd: ") + std::strerror(errno);
    Close();
    return Fail(Error::kIoError, why);
  }
  return Expected<void>::Ok();
}

void ShutdownSignal::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (mask_saved_) pthread_sigmask(SIG_SETMASK, &old_mask_, nullptr);
  mask_saved_ = false;
}

int ShutdownSignal::Take() {
  int last = 0;
  signalfd_siginfo info{};
  while (fd_ >= 0 && ::read(fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
    last = static_cast<int>(info.ssi_signo);
  }
  return last;
}

}  // namespace volcomp::hal::linux_board
