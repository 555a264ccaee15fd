// hal::SlowIo over a GpioBackend (libgpiod or fake) for the Linux board. Refresh(now) reads every
// input once and debounces in software (`debounce_ms`; e-stop and drive alarm go active at once,
// inactive only after the debounce time); Read() returns the debounced level, Write() drives an
// output when its level changes. Backend failures are counted (last_failure()); an unreadable
// line keeps its level. Threading: one thread (the main loop). docs/linux-board.md, "GPIO wiring".
#pragma once

#include <cstdint>
#include <optional>

#include "volcomp/hal/linux/gpio_lines.hpp"
#include "volcomp/hal/slow_io.hpp"

namespace volcomp::hal::linux_board {

class LinuxSlowIo final : public SlowIo {
 public:
  struct Options {
    uint32_t debounce_ms = 5;
  };

  LinuxSlowIo(GpioBackend* backend, const Options& options)
      : backend_(backend), debounce_ns_(uint64_t{options.debounce_ms} * 1000000u) {}
  ~LinuxSlowIo() = default;

  /// Reads the inputs and updates the debounced levels at time `now_ns` (monotonic).
  void Refresh(uint64_t now_ns);

  /// The last raw (undebounced) level of an input.
  bool raw(InputLine line) const { return raw_[static_cast<int>(line)]; }
  /// The level last written to an output.
  bool output(OutputLine line) const { return out_[static_cast<int>(line)]; }
  uint64_t errors() const { return errors_; }
  const std::optional<Failure>& last_failure() const { return last_failure_; }

 private:
  bool DoRead(InputLine line) override { return stable_[static_cast<int>(line)]; }
  void DoWrite(OutputLine line, bool level) override;
  static bool FailSafe(int line) {
    return line == static_cast<int>(InputLine::kEStop) ||
           line == static_cast<int>(InputLine::kDriveAlarm);
  }

  GpioBackend* backend_;
  uint64_t debounce_ns_;
  bool primed_ = false;
  bool raw_[kInputLineCount] = {};
  bool stable_[kInputLineCount] = {};
  bool pending_[kInputLineCount] = {};       // a change is being timed
  uint64_t since_ns_[kInputLineCount] = {};  // when the raw level first differed
  bool out_[kOutputLineCount] = {};
  bool out_written_[kOutputLineCount] = {};
  uint64_t errors_ = 0;
  std::optional<Failure> last_failure_;
};

}  // namespace volcomp::hal::linux_board
