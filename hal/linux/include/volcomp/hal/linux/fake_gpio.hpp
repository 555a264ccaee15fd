// A fake GPIO backend: the slow lines without any GPIO hardware (tests, development machines,
// user-mode-linux, whose kernel has no GPIOLIB). Always built.
//
// In memory: SetInput() sets an input's logical level, output() reads what the firmware drove.
// With a state file (the `gpio = fake:PATH` configuration): inputs also come from PATH, a text
// file of "name=0|1" lines ('#' starts a comment; the names of gpio_lines.hpp; missing file or
// missing names mean inactive), re-read whenever its modification time or size changes (one
// stat() per ReadInputs()). Outputs are written to PATH.out as "name=0|1" lines, replaced
// atomically (temporary file + rename) when an output changes. So a shell can drive the inputs:
//   echo "estop=1" > /tmp/board.gpio
// The line specs of the configuration are ignored: every line exists.
//
// Thread-safety: one thread.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "volcomp/hal/linux/gpio_lines.hpp"

namespace volcomp::hal::linux_board {

class FakeGpio final : public GpioBackend {
 public:
  explicit FakeGpio(std::string state_file = "") : path_(std::move(state_file)) {}

  Expected<void> Open(const GpioConfig& config) override;
  Expected<void> ReadInputs(bool* levels) override;
  Expected<void> WriteOutput(OutputLine line, bool active) override;
  std::string Describe() const override;

  /// Sets an input in memory (overridden by the state file's value when it names the line).
  void SetInput(InputLine line, bool active) { memory_[static_cast<int>(line)] = active; }
  bool output(OutputLine line) const { return out_[static_cast<int>(line)]; }
  /// How many times the state file was (re)read.
  uint32_t file_reads() const { return file_reads_; }

 private:
  Expected<void> LoadFile();
  Expected<void> SaveOutputs() const;

  std::string path_;
  bool memory_[kInputLineCount] = {};
  bool from_file_[kInputLineCount] = {};
  bool file_has_[kInputLineCount] = {};
  bool out_[kOutputLineCount] = {};
  int64_t mtime_ns_ = -1;
  int64_t file_size_ = -1;
  uint32_t file_reads_ = 0;
};

}  // namespace volcomp::hal::linux_board
