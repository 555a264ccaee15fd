// Debounced slow lines over a GPIO backend.
#include "volcomp/hal/linux/linux_slow_io.hpp"

namespace volcomp::hal::linux_board {

void LinuxSlowIo::Refresh(uint64_t now_ns) {
  const Expected<void> read = backend_->ReadInputs(raw_);
  if (!read.ok()) {
    ++errors_;
    last_failure_ = read.error();
  }
  if (!primed_) {  // the first reading has no history to debounce against
    for (int i = 0; i < kInputLineCount; ++i) stable_[i] = raw_[i];
    primed_ = true;
    return;
  }
  for (int i = 0; i < kInputLineCount; ++i) {
    if (raw_[i] == stable_[i]) {
      pending_[i] = false;
      continue;
    }
    if (FailSafe(i) && raw_[i]) {
      stable_[i] = true;
      pending_[i] = false;
      continue;
    }
    if (!pending_[i]) {
      pending_[i] = true;
      since_ns_[i] = now_ns;
    }
    if (now_ns - since_ns_[i] >= debounce_ns_) {
      stable_[i] = raw_[i];
      pending_[i] = false;
    }
  }
}

void LinuxSlowIo::DoWrite(OutputLine line, bool level) {
  const int i = static_cast<int>(line);
  if (i < 0 || i >= kOutputLineCount) return;
  if (out_written_[i] && out_[i] == level) return;
  const Expected<void> written = backend_->WriteOutput(line, level);
  if (!written.ok()) {
    ++errors_;
    last_failure_ = written.error();
    return;  // retried at the next Write()
  }
  out_[i] = level;
  out_written_[i] = true;
}

}  // namespace volcomp::hal::linux_board
