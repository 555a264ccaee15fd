// The board's slow lines on Linux GPIO: the line names (home0..home5, enable, estop, drive_alarm,
// write_enable in; ready, compensating, fault out), a line spec "CHIP:OFFSET [flags]" or
// "NAME [flags]" per line, and the backend interface that reads and drives them (libgpiod, or a
// fake). Levels are logical (true = active, after active-low). Threading: one thread (the main
// loop). Spec syntax and wiring: docs/linux-board.md, "GPIO wiring".
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::hal::linux_board {

inline constexpr int kInputLineCount = static_cast<int>(InputLine::kCount);
inline constexpr int kOutputLineCount = static_cast<int>(OutputLine::kCount);

enum class Bias : uint8_t { kAsIs, kDisable, kPullUp, kPullDown };

struct GpioLineSpec {
  bool used = false;
  std::string chip;  // empty: look the line up by `line_name`
  unsigned offset = 0;
  std::string line_name;  // used when `chip` is empty
  bool active_low = false;
  Bias bias = Bias::kAsIs;
};

struct GpioConfig {
  GpioLineSpec input[kInputLineCount];
  GpioLineSpec output[kOutputLineCount];
  std::string consumer = "volcomp";  // shown by gpioinfo
};

/// Parses a line spec (see above); kInvalidArgument saying what is wrong with `text`.
Expected<GpioLineSpec> ParseGpioLineSpec(const std::string& text);
/// The spec back as text ("gpiochip0:17 active-low pull-up").
std::string FormatGpioLineSpec(const GpioLineSpec& spec);

const char* InputLineName(InputLine line);
const char* OutputLineName(OutputLine line);
/// Looks a name up; false when it names no line.
bool InputLineFromName(const std::string& name, InputLine* line);
bool OutputLineFromName(const std::string& name, OutputLine* line);

class GpioBackend {
 public:
  virtual ~GpioBackend() = default;
  /// Requests the configured lines; a failure names the line and the cause.
  virtual Expected<void> Open(const GpioConfig& config) = 0;
  /// Reads every input into levels[0 .. kInputLineCount) (unconfigured lines: false). On a
  /// failure the lines that could not be read keep their previous values.
  virtual Expected<void> ReadInputs(bool* levels) = 0;
  /// Drives an output (unconfigured outputs are ignored).
  virtual Expected<void> WriteOutput(OutputLine line, bool active) = 0;
  /// "libgpiod 1.6.3", "fake", ...
  virtual std::string Describe() const = 0;
};

}  // namespace volcomp::hal::linux_board
