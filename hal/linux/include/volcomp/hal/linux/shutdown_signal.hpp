// Clean shutdown on SIGINT / SIGTERM (and SIGHUP) through a signalfd: the signals are blocked for
// the calling thread (call Open() in main() before starting other threads, so they inherit the
// mask) and arrive as readable data on fd(), which the event loop polls with its other fds.
// Nothing runs in signal context.
//
// Thread-safety: one thread per object.
#pragma once

#include <signal.h>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::hal::linux_board {

class ShutdownSignal {
 public:
  ShutdownSignal() = default;
  ~ShutdownSignal() { Close(); }
  ShutdownSignal(const ShutdownSignal&) = delete;
  ShutdownSignal& operator=(const ShutdownSignal&) = delete;

  /// Blocks SIGINT, SIGTERM and SIGHUP and opens the signalfd; kIoError with the reason when it
  /// cannot (the mask is restored then).
  Expected<void> Open();
  /// Closes the fd and restores the previous signal mask.
  void Close();
  int fd() const { return fd_; }

  /// Reads pending signals; returns the last signal number received, or 0 when none is pending.
  int Take();

 private:
  int fd_ = -1;
  bool mask_saved_ = false;
  sigset_t old_mask_{};
};

}  // namespace volcomp::hal::linux_board
