// What the QEMU cycle benches share (cycle_bench.cpp: the tick; main_loop_bench.cpp: the main
// loop): the scenario protocol of toolchain/cyclemodel/cm4cost.py, and table flash in RAM.
#pragma once

#include <cstdint>

#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/stm32g4/drivers.hpp"

/// The scenario marker: cm4cost.py attributes every top-level call of a scenario's symbol after
/// the mark to that scenario (its own section, so it is in the traced range).
extern "C" void volcomp_bench_mark();

namespace volcomp::target {

/// Prints `SCENARIO <name> <symbol>` (semihosting) and marks the trace.
void Scenario(const char* name, const char* symbol);

/// Table flash in RAM, 64 KB of 2 KB sectors. CPU work per operation at least the STM32 driver's
/// (hal/stm32g4 StmFlash): a page erase there is a register sequence and a busy wait (wall time,
/// not CPU), here 512 word stores; a 64-bit program is two word stores (and the busy wait on the
/// board). Programming clears bits only, as NOR flash does.
class BenchFlash final : public hal::Flash {
 public:
  static constexpr uint32_t kSectors = 32, kSectorBytes = 2048;

 private:
  uint32_t DoSize() const override { return sizeof words_; }
  uint32_t DoSectorSize() const override { return kSectorBytes; }
  uint32_t DoProgramUnit() const override { return 8; }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t n) override;
  const uint8_t* DoMap(uint32_t offset) const override {
    return reinterpret_cast<const uint8_t*>(words_) + offset;
  }
  uint32_t words_[kSectors * kSectorBytes / 4] = {};
};

/// Home switches closed once `homed`, no fault lines, no enable or write-enable wiring.
class BenchLines final : public hal::SlowIo {
 public:
  bool homed = false;

 private:
  bool DoRead(hal::InputLine line) override {
    return homed && static_cast<uint8_t>(line) < static_cast<uint8_t>(hal::InputLine::kEnable);
  }
  void DoWrite(hal::OutputLine, bool) override {}
};

/// The step/dir image's application type, on the STM32 drivers (registers in RAM on QEMU).
using BenchIo = firmware::StepDirIo<stm32g4::StepIo>;
using BenchApp = firmware::BoardApp<BenchIo>;

}  // namespace volcomp::target
