// The board firmware (firmware/app BoardApp) inside a LinuxCNC HAL component: the only place that
// knows BoardApp's API. Devices: the tick I/O StepDirIo<HalStepIo> (step/dir on pins), a
// ThreadTickTimer (the base thread calls Tick() every kPeriodsPerTick periods,
// thread_board_config.hpp), slow lines from
// pins, a RAM flash for the table store, no CAN port (the table comes from an image file through
// BoardApp::ActivateImage).
//
// All calls from LinuxCNC's base thread (one thread: Tick() and Poll() never run concurrently).
#pragma once

#include <cstdint>

#include "board/hal_step_io.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/config/board_config.hpp"

namespace volcomp::linuxcnc {

/// Slow input lines of the board, set from HAL pins before each Poll().
struct BoardLines {
  bool home[HalStepIo::kAxes] = {};
  bool enable = false;
  bool estop = false;
  bool drive_alarm = false;
};

/// Live state for HAL output pins.
struct BoardState {
  bool ready = false, compensating = false, fault = false, referenced = false;
  int32_t commanded[HalStepIo::kAxes] = {};   // the board's input position (steps)
  int32_t correction[HalStepIo::kAxes] = {};  // whole-step correction in the output
  int32_t output[HalStepIo::kAxes] = {};      // the board's output position (steps)
  int32_t backlog[HalStepIo::kAxes] = {};     // steps owed to the drive
  uint32_t max_backlog = 0;
  uint32_t overruns = 0;
  uint32_t table_crc32 = 0;
};

class BoardGlue {
 public:
  /// Creates the devices for a base thread of `period_ns` (output DIR high for negative moves when
  /// `dir_negative_high`) and starts the firmware with `config`. The firmware applies it to the
  /// step I/O and the tick timer, which refuse what the pins and the thread cannot do
  /// (kConfigInvalid; refused_by() names the part). Once per process.
  Status Start(const BoardConfig& config, uint32_t period_ns, bool dir_negative_high);
  canopen::ConfigPart refused_by() const;
  /// The step I/O on pins (valid after Start(), also when it failed).
  HalStepIo& io();
  /// True while the firmware's tick timer runs (Tick() is to be called).
  bool ticking() const;
  /// Validates and activates an image (the bytes must stay valid while it is active).
  Status ActivateImage(const uint8_t* image, uint32_t size);
  void Tick();
  void Poll(const BoardLines& lines);
  void ReadState(BoardState* s) const;
};

}  // namespace volcomp::linuxcnc
