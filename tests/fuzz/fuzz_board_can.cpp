// Fuzz target: the board's CANopen node (NMT, SDO server, object dictionary, table staging in
// flash) fed with arbitrary frame sequences while the control tick runs. Each 10-byte record of
// the input is one event: byte 0 selects the COB-ID (NMT, this node's SDO, another node, or raw),
// byte 1 the DLC, bytes 2-9 the data; every record also advances time by 8..512 ticks (data byte 6)
// and moves axis 1 by data byte 7 / 16 steps. Invariants: no crash or UB,
// every frame the board sends is a valid CAN frame, and the active table (none at start, so any
// table must have come through a complete verified upload) always validates.
#include <cstdint>
#include <cstdlib>

#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace volcomp;
  static const BoardConfig config = DefaultBoardConfig();
  hal::mock::MockClock clock;
  hal::mock::MockSlowIo io(&clock, nullptr);
  hal::mock::MockFlash tables(64 * 1024, 2048, 8, &clock, nullptr);
  hal::mock::MockFlash settings(8 * 1024, 2048, 8, &clock, nullptr);
  hal::mock::MockCan can(&clock, nullptr, 256);
  hal::mock::MockStepIo step_io(config, nullptr);
  firmware::StepDirIo<hal::mock::MockStepIo> tick_io(&step_io);
  firmware::BoardApp<firmware::StepDirIo<hal::mock::MockStepIo>> app(
      {&tick_io, &io, &tables, &settings, &can, &clock});
  io.SetInput(hal::InputLine::kWriteEnable, true);
  io.SetInput(hal::InputLine::kEnable, true);
  if (!app.Start(config).ok()) std::abort();
  for (size_t off = 0; off + 10 <= size; off += 10) {
    const uint8_t* r = data + off;
    CanFrame f;
    switch (r[0] & 3) {
      case 0:
        f.id = 0x000;
        break;
      case 1:
        f.id = 0x610;
        break;
      case 2:
        f.id = 0x600 | (r[0] >> 2);
        break;
      default:
        f.id = (uint32_t{r[0]} << 3 | r[1]) & 0x7FF;
        break;
    }
    f.dlc = r[1] % 9;
    for (int i = 0; i < 8; ++i) f.data[i] = r[2 + i];
    can.Inject(f);
    step_io.add_steps(0, static_cast<int8_t>(r[9]) / 16);
    const int ticks = (1 + r[8] % 64) * 8;  // up to ~10 ms per record
    for (int t = 0; t < ticks; ++t) {
      step_io.set_tick_start_ns(clock.now());
      app.Tick();
      clock.Advance(20000);
    }
    app.Poll();
    for (const CanFrame& out : can.TakeSent()) {
      if (!out.valid()) std::abort();
    }
  }
  if (app.objects().device_state() & canopen::kStateTableActive) {
    const firmware::TableStore& t = app.tables();
    if (!table::ParseImage(t.active_data(), t.active_size()).ok()) std::abort();
  }
  return 0;
}
