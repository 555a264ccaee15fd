// A fake GPIO backend: the slow lines without GPIO hardware (tests, development machines,
// user-mode-linux). In memory (SetInput(), output()), or with a state file PATH of "name=0|1"
// lines (inputs re-read when it changes; outputs written atomically to PATH.out). Every line
// exists; line specs are ignored. Threading: one thread. docs/linux-board.md, "GPIO wiring".
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
