// Link check: uses the core's public API from an entry point with no C/C++ runtime linked.
// Only the four memory primitives a freestanding compiler may call are provided
// (toolchain/runtime/mem_primitives.cpp, the same as in the Cortex-M4F images).
#include <cstddef>
#include <cstdint>

#include "volcomp/base/crc32.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/gateway_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/output/step_output.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/table/table_writer.hpp"

namespace {

struct NullStepIo {
  volcomp::Status Configure(const volcomp::BoardConfig&) { return volcomp::Status::Ok(); }
  void ReadCounters(uint32_t* counters) {
    for (int i = 0; i < 6; ++i) counters[i] = 0;
  }
  void Apply(const volcomp::PulsePlan*) {}
};

class NullIo final : public volcomp::hal::SlowIo {
  bool DoRead(volcomp::hal::InputLine) override { return false; }
  void DoWrite(volcomp::hal::OutputLine, bool) override {}
};

class NullCan final : public volcomp::hal::CanPort {
  volcomp::Status DoSend(const volcomp::CanFrame&) override { return volcomp::Status(); }
  bool DoReceive(volcomp::CanFrame*) override { return false; }
  volcomp::Status DoSetBitrate(uint32_t) override { return volcomp::Status(); }
};

class NullTickTimer final : public volcomp::hal::TickTimer {
  volcomp::Status DoSetRate(uint32_t) override { return volcomp::Status(); }
  volcomp::Status DoStart() override { return volcomp::Status(); }
  void DoStop() override {}
  uint32_t DoRateHz() const override { return 0; }
};

class NullClock final : public volcomp::hal::Clock {
  uint64_t DoNowNs() override { return 0; }
};

class NullFlash final : public volcomp::hal::Flash {
  uint32_t DoSize() const override { return sizeof bytes_; }
  uint32_t DoSectorSize() const override { return 64; }
  uint32_t DoProgramUnit() const override { return 8; }
  volcomp::Status DoErase(uint32_t) override { return volcomp::Status(); }
  volcomp::Status DoProgram(uint32_t, const uint8_t*, uint32_t) override {
    return volcomp::Status();
  }
  const uint8_t* DoMap(uint32_t offset) const override { return bytes_ + offset; }
  alignas(4) uint8_t bytes_[256] = {};
};

}  // namespace

extern "C" {
// Called if a pure virtual function is ever invoked (never here); part of the ABI, not the runtime.
void __cxa_pure_virtual() {
  for (;;) {
  }
}

// Never executed: the point is that this links.
[[noreturn]] void volcomp_freestanding_entry() {
  alignas(4) static uint8_t image[512];
  static int16_t values[2 * 2 * 2 * 3];
  volcomp::table::GridSpec grid;
  for (auto& d : grid.dim) d = {2, 0, 100};
  grid.values.i16 = values;
  volcomp::table::ImageSpec spec;
  spec.axis_count = 3;
  spec.axes[0] = {'X', volcomp::table::AxisKind::kLinear, 1000000};
  spec.axes[1] = {'Y', volcomp::table::AxisKind::kLinear, 1000000};
  spec.axes[2] = {'Z', volcomp::table::AxisKind::kLinear, 1000000};
  spec.grid = &grid;
  volatile uint32_t sink = 0;
  if (volcomp::table::WriteImage(spec, image, sizeof image).ok()) {
    const auto view = volcomp::table::ParseImage(image, sizeof image);
    static volcomp::ControlTick tick;
    constexpr volcomp::BoardConfig kConfig = volcomp::DefaultBoardConfig();
    if (view.ok() && tick.Configure(kConfig).ok()) {
      volcomp::PreparedTable t;
      if (t.Prepare(*view, kConfig).ok()) {
        int32_t pos[3] = {0, 0, 0};
        tick.compensator().SetTable(t, pos);
      }
      uint32_t counters[3] = {1, 2, 3};
      volcomp::PulsePlan plans[3];
      tick.Run(counters);
      static volcomp::StepOutput output;
      if (output.Configure(kConfig).ok()) output.Plan(tick.targets(), plans);
      sink = plans[0].count + volcomp::ComputeCrc32(image, 8);
    }
  }
  static NullStepIo step_io;
  static volcomp::firmware::StepDirIo<NullStepIo> tick_io(&step_io);
  static NullIo io;
  static NullFlash flash;
  static volcomp::firmware::BoardApp<volcomp::firmware::StepDirIo<NullStepIo>> app(
      {&tick_io, &io, &flash});
  if (app.Start(volcomp::DefaultBoardConfig()).ok()) {
    app.Poll();
    app.Tick();
  }
  // The CAN gateway application (node, CSP gateway, frame routing) links without a runtime too.
  static NullCan controller, drives;
  static NullClock clock;
  static NullFlash gateway_flash;
  static NullTickTimer tick_timer;
  static volcomp::firmware::GatewayApp gateway(
      {&controller, &drives, &io, &gateway_flash, nullptr, &clock, &tick_timer});
  if (gateway.Start(volcomp::BoardSettings(), volcomp::gateway::GatewayConfig()).ok()) {
    gateway.PumpFrames();
    gateway.Tick();
    gateway.Poll();
  }
  (void)sink;
  for (;;) {
  }
}
}
