// BoardApp on HAL devices (see the header). One instance per process (LinuxCNC loads a component
// once), in static storage: no heap.
#include "board/board_glue.hpp"

#include <cstring>
#include <new>

#include "board/thread_board_config.hpp"
#include "board/thread_tick_timer.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"

namespace volcomp::linuxcnc {
namespace {

// NOR flash in RAM for the firmware's table store (erase -> 0xFF, program clears bits).
class RamFlash final : public hal::Flash {
 public:
  static constexpr uint32_t kSize = 1u << 21, kSector = 4096, kUnit = 8;
  RamFlash() { std::memset(bytes_, 0xFF, sizeof bytes_); }

 private:
  uint32_t DoSize() const override { return kSize; }
  uint32_t DoSectorSize() const override { return kSector; }
  uint32_t DoProgramUnit() const override { return kUnit; }
  Status DoErase(uint32_t offset) override {
    std::memset(bytes_ + offset, 0xFF, kSector);
    return Status::Ok();
  }
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override {
    for (uint32_t i = 0; i < bytes; ++i) bytes_[offset + i] &= data[i];
    return Status::Ok();
  }
  const uint8_t* DoMap(uint32_t offset) const override { return bytes_ + offset; }
  alignas(8) uint8_t bytes_[kSize];
};

class PinLines final : public hal::SlowIo {
 public:
  BoardLines in;
  bool out[static_cast<int>(hal::OutputLine::kCount)] = {};

 private:
  bool DoRead(hal::InputLine line) override {
    const int i = static_cast<int>(line);
    if (i < HalStepIo::kAxes) return in.home[i];
    switch (line) {
      case hal::InputLine::kEnable:
        return in.enable;
      case hal::InputLine::kEStop:
        return in.estop;
      case hal::InputLine::kDriveAlarm:
        return in.drive_alarm;
      default:
        return false;
    }
  }
  void DoWrite(hal::OutputLine line, bool level) override { out[static_cast<int>(line)] = level; }
};

using TickIo = firmware::StepDirIo<HalStepIo>;
using App = firmware::BoardApp<TickIo>;

// Constructed once by Start() (the thread period is known only then).
template <class T>
struct Slot {
  alignas(T) unsigned char bytes[sizeof(T)];
  T* p = nullptr;
};

RamFlash g_flash;
PinLines g_lines;
Slot<HalStepIo> g_io;
Slot<ThreadTickTimer> g_timer;
Slot<TickIo> g_tick_io;
Slot<App> g_app;

}  // namespace

Status BoardGlue::Start(const BoardConfig& config, uint32_t period_ns, bool dir_negative_high) {
  if (g_app.p != nullptr) return Error::kBusy;
  g_io.p = new (g_io.bytes) HalStepIo(period_ns, dir_negative_high);
  g_timer.p = new (g_timer.bytes) ThreadTickTimer(period_ns, kPeriodsPerTick);
  g_tick_io.p = new (g_tick_io.bytes) TickIo(g_io.p);
  App::Devices d;
  d.tick_io = g_tick_io.p;
  d.io = &g_lines;
  d.table_flash = &g_flash;
  d.tick_timer = g_timer.p;
  g_app.p = new (g_app.bytes) App(d);
  return g_app.p->Start(config);
}

canopen::ConfigPart BoardGlue::refused_by() const { return g_app.p->config_refused_by(); }

HalStepIo& BoardGlue::io() { return *g_io.p; }

bool BoardGlue::ticking() const { return g_timer.p->running(); }

Status BoardGlue::ActivateImage(const uint8_t* image, uint32_t size) {
  return g_app.p->ActivateImage(image, size);
}

void BoardGlue::Tick() { g_app.p->Tick(); }

void BoardGlue::Poll(const BoardLines& lines) {
  g_lines.in = lines;
  g_app.p->Poll();
}

void BoardGlue::ReadState(BoardState* s) const {
  const ControlTick& e = g_app.p->control_tick();
  const StepOutput& out = g_app.p->tick_io().output();
  s->ready = g_lines.out[static_cast<int>(hal::OutputLine::kReady)];
  s->compensating = g_lines.out[static_cast<int>(hal::OutputLine::kCompensating)];
  s->fault = g_lines.out[static_cast<int>(hal::OutputLine::kFault)];
  s->referenced = e.all_referenced();
  uint32_t max_backlog = 0;
  for (uint8_t a = 0; a < HalStepIo::kAxes && a < out.axis_count(); ++a) {
    s->commanded[a] = e.commanded(a);
    s->correction[a] = e.correction_steps(a);
    s->output[a] = out.position(a);
    s->backlog[a] = out.backlog(a, e.target(a));
    if (out.max_backlog(a) > max_backlog) max_backlog = out.max_backlog(a);
  }
  s->max_backlog = max_backlog;
  s->overruns = out.overruns();
  s->table_crc32 = e.compensator().table_crc32();
}

}  // namespace volcomp::linuxcnc
