// Debounced slow lines over a GPIO backend.
#include "volcomp/hal/linux/linux_slow_io.hpp"

namespace volcomp::hal::linux_board {

void LinuxSlowIo::Refresh(uint64_t now_ns) {
  const std::string why = backend_->ReadInputs(raw_);
  if (!why.empty()) {
    ++errors_;
    last_error_ = why;
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
  const std::string why = backend_->WriteOutput(line, level);
  if (!why.empty()) {
    ++errors_;
    last_error_ = why;
    return;  // retried at the next Write()
  }
  out_[i] = level;
  out_written_[i] = true;
}

}  // namespace volcomp::hal::linux_board
