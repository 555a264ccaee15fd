// BoardApp on HAL devices (see the header). One instance per process (LinuxCNC loads a component
// once), in static storage: no heap.
#include "board/board_glue.hpp"

#include <cstring>
#include <new>

#include "volcomp/firmware/board_app.hpp"
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

using App = firmware::BoardApp<HalStepIo>;

RamFlash g_flash;
PinLines g_lines;
alignas(App) unsigned char g_app_storage[sizeof(App)];
App* g_app = nullptr;

}  // namespace

Status BoardGlue::Start(const BoardConfig& config, HalStepIo* step_io) {
  App::Devices d;
  d.step_io = step_io;
  d.io = &g_lines;
  d.table_flash = &g_flash;
  if (g_app == nullptr) g_app = new (g_app_storage) App(d);
  return g_app->Start(config);
}

Status BoardGlue::ActivateImage(const uint8_t* image, uint32_t size) {
  return g_app->ActivateImage(image, size);
}

void BoardGlue::Tick() { g_app->Tick(); }

void BoardGlue::Poll(const BoardLines& lines) {
  g_lines.in = lines;
  g_app->Poll();
}

void BoardGlue::ReadState(BoardState* s) const {
  const ControlTick& e = g_app->engine();
  s->ready = g_lines.out[static_cast<int>(hal::OutputLine::kReady)];
  s->compensating = g_lines.out[static_cast<int>(hal::OutputLine::kCompensating)];
  s->fault = g_lines.out[static_cast<int>(hal::OutputLine::kFault)];
  s->referenced = e.all_referenced();
  uint32_t max_backlog = 0;
  for (uint8_t a = 0; a < HalStepIo::kAxes && a < e.axis_count(); ++a) {
    s->commanded[a] = e.commanded(a);
    s->correction[a] = e.correction_steps(a);
    s->output[a] = e.output_position(a);
    s->backlog[a] = e.backlog(a);
    if (e.max_backlog(a) > max_backlog) max_backlog = e.max_backlog(a);
  }
  s->max_backlog = max_backlog;
  s->overruns = e.overruns();
  s->table_crc32 = e.compensator().table_crc32();
}

}  // namespace volcomp::linuxcnc
