// Fuzz target: the board's CANopen node (NMT, SDO server, object dictionary, table staging in
// flash) fed with arbitrary frame sequences while the control tick runs.
//
// Input: 10-byte records, one event each. Byte 0 selects the COB-ID (NMT, this node's SDO,
// another node's SDO, or raw), byte 1 the DLC, bytes 2-9 the data. Bytes 8 and 9 (data bytes 6
// and 7) also drive the machine and the time:
//   * byte 8 = 0b01xxxxxx with byte 9 = 0xNF moves axis 1 by N steps (signed nibble, -8..7) and
//     one control tick runs (1 ms). Motion is rare in random bytes (1 record in 64), as on a
//     machine being configured over CAN;
//   * then the clock advances by (byte 8 & 0x3F) ms and the main loop runs once: the frames of the
//     records since its last pass are received together (as on a bus, where a block download's
//     segments arrive in bursts). With 0 ms and no motion the frame waits for the next pass;
//   * byte 8 = 0xFF with byte 9 = 0 is a rest instead: the main loop runs, then ticks, one per
//     millisecond, until the board has seen no input step for 100 ms (activation needs that; at
//     most 101 ticks, one if it already has), then the main loop again.
//
// The board is the real BoardApp in the default configuration at the lowest tick rate it accepts
// (1 kHz, so a rest costs at most 101 ticks; a faster rate stored over SDO and taken at reset node
// makes a rest too short to count as still, and activation is refused), on the mock slow I/O and
// small mock flashes (8 KiB of tables: two 4 KiB banks, a larger image is refused as too large,
// which is one of the paths explored; 4 KiB of settings), with a step I/O that only counts input
// steps and a CAN port that queues the records' frames and folds what the board sends into a digest
// (FuzzStepIo, FuzzCan: the output pulses are not what this target explores). It is built and
// started once; every input starts from a copy of that started board (Rig::Reset: the board's
// bytes, the devices and the flash content copied back), so an input costs its records, not a
// board. That the reset is complete is checked: an input run a second time right after itself
// (every input in the replay test, every 1024th while fuzzing) must send exactly the same frames.
//
// Invariants: no crash or UB (ASan, UBSan), the active table (none at start, so any table came
// through a complete verified upload) always validates, and the same input gives the same frames.
// (An invalid frame never reaches the bus: hal::CanPort::Send refuses it.)
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <vector>

#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace {

using namespace volcomp;  // NOLINT(build/namespaces): test harness

// The step I/O of the fuzzed board: input counters the records move, output plans dropped (this
// target explores the CAN side; the mock with its drive models costs more than the board's tick).
class FuzzStepIo {
 public:
  Status Configure(const BoardConfig& config) {
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
      const uint32_t bits = config.axis[a].input_counter_bits;
      mask_[a] = bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u;
    }
    return Status::Ok();
  }
  void ReadCounters(uint32_t* counters) const {
    for (uint8_t a = 0; a < table::kMaxAxes; ++a) counters[a] = counters_[a];
  }
  void Apply(const PulsePlan*) {}
  void add_steps(uint8_t axis, int32_t delta) {
    counters_[axis] = (counters_[axis] + static_cast<uint32_t>(delta)) & mask_[axis];
  }

 private:
  uint32_t counters_[table::kMaxAxes] = {};
  uint32_t mask_[table::kMaxAxes] = {};
};

// The CAN port of the fuzzed board: the records' frames in (up to kRxFrames waiting for one
// main-loop pass), the frames out folded into a digest (FNV-1a over id, flags, DLC and data)
// instead of stored.
class FuzzCan : public hal::CanPort {
 public:
  static constexpr uint32_t kRxFrames = 16;
  bool full() const { return rx_count_ == kRxFrames; }
  bool empty() const { return rx_count_ == 0; }
  void Inject(const CanFrame& f) { rx_[(rx_head_ + rx_count_++) % kRxFrames] = f; }
  void Clear() {
    rx_count_ = 0;
    digest_ = kFnvBasis;
  }
  uint64_t digest() const { return digest_; }

 private:
  static constexpr uint64_t kFnvBasis = 0xCBF29CE484222325ull;
  void Mix(uint32_t v) {
    digest_ ^= v;
    digest_ *= 0x100000001B3ull;
  }
  Status DoSend(const CanFrame& f) override {
    Mix(f.id | (f.extended ? 1u << 31 : 0) | (f.rtr ? 1u << 30 : 0));
    Mix(f.dlc);
    for (int i = 0; i < f.dlc; ++i) Mix(f.data[i]);
    return Status::Ok();
  }
  Status DoSetBitrate(uint32_t) override { return Status::Ok(); }  // any rate: not explored here
  bool DoReceive(CanFrame* f) override {
    if (rx_count_ == 0) return false;
    *f = rx_[rx_head_];
    rx_head_ = (rx_head_ + 1) % kRxFrames;
    --rx_count_;
    return true;
  }

  CanFrame rx_[kRxFrames];
  uint32_t rx_head_ = 0, rx_count_ = 0;
  uint64_t digest_ = kFnvBasis;
};

using TickIo = firmware::StepDirIo<FuzzStepIo>;
using App = firmware::BoardApp<TickIo>;

#ifdef VOLCOMP_FUZZ_REPLAY
constexpr uint64_t kRecheckEvery = 1;
#else
constexpr uint64_t kRecheckEvery = 1024;
#endif
constexpr uint8_t kRestTime = 0xFF;  // with byte 9 = 0: a rest
constexpr uint32_t kRestTicks = firmware::kStillMs * kMinTickHz / 1000 + 1;

BoardConfig FuzzConfig() {
  BoardConfig c = DefaultBoardConfig();
  c.tick_hz = kMinTickHz;
  return c;
}

// Everything an input can change, restored by Reset().
class Rig {
 public:
  // Starts the board once (on erased flash, at time 0) and keeps that state as the snapshot every
  // input starts from.
  Rig()
      : config_(FuzzConfig()),
        tables_(8 * 1024, 1024, 8, &clock_, nullptr),
        settings_(4 * 1024, 1024, 8, &clock_, nullptr),
        io_(&clock_, nullptr) {
    io_.SetInput(hal::InputLine::kWriteEnable, true);
    io_.SetInput(hal::InputLine::kEnable, true);
    App* app = new (app_) App({&tick_io_, &io_, &tables_, &settings_, &can_, &clock_});
    if (!app->Start(config_).ok()) std::abort();
    std::memcpy(started_app_, app_, sizeof(App));
    started_io_ = io_;
    started_step_io_ = step_io_;
    started_tick_io_ = tick_io_;
    started_tables_ = tables_.raw();
    started_settings_ = settings_.raw();
  }

  // The board as it was just after Start(): its bytes copied back (it holds no resource, only
  // values and pointers to its own parts and to the devices, which stay where they are), the
  // devices and the flash content restored. The flash is copied back whole (12 KiB) every time:
  // a program the mock refuses (a bit to raise from 0 to 1) has already written the bytes before
  // that one, and counts nothing.
  void Reset() {
    std::memcpy(tables_.raw().data(), started_tables_.data(), started_tables_.size());
    std::memcpy(settings_.raw().data(), started_settings_.data(), started_settings_.size());
    can_.Clear();
    clock_.Set(0);
    io_ = started_io_;
    step_io_ = started_step_io_;
    tick_io_ = started_tick_io_;
    std::memcpy(app_, started_app_, sizeof(App));
  }

  // Runs one input; returns the digest of every frame the board sent.
  uint64_t Run(const uint8_t* data, size_t size) {
    Reset();
    for (size_t off = 0; off + 10 <= size; off += 10) Record(data + off);
    if (!can_.empty()) app().Poll();  // frames still waiting for a main-loop pass
    if (app().objects().device_state() & canopen::kStateTableActive) {
      const firmware::TableStore& t = app().tables();
      if (!table::ParseImage(t.active_data(), t.active_size()).ok()) std::abort();
    }
    return can_.digest();
  }

 private:
  App& app() { return *std::launder(reinterpret_cast<App*>(app_)); }
  void Tick() {
    app().Tick();
    clock_.Advance(1000000);
  }

  void Record(const uint8_t* r) {
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
    if (can_.full()) app().Poll();
    can_.Inject(f);
    const bool moves = (r[8] & 0xC0) == 0x40 && (r[9] & 0x0F) == 0x0F;
    const int steps = moves ? static_cast<int8_t>(r[9]) >> 4 : 0;
    step_io_.add_steps(0, steps);
    if (r[8] == kRestTime && r[9] == 0) {
      // The frames waiting are received, then ticks run until the board has seen no input step
      // for kStillMs (at least one: a reference or a table switch waits for the tick).
      app().Poll();
      do {
        Tick();
      } while (app().control_tick().idle_ticks() < kRestTicks);
    } else {
      if (steps != 0) Tick();
      const uint32_t ms = r[8] & 0x3Fu;
      if (ms == 0 && steps == 0) return;  // arrives in the same main-loop pass as the next frame
      clock_.Advance(uint64_t{ms} * 1000000);
    }
    app().Poll();
  }

  BoardConfig config_;
  hal::mock::MockClock clock_;
  hal::mock::MockFlash tables_, settings_;
  FuzzCan can_;
  hal::mock::MockSlowIo io_, started_io_{nullptr, nullptr};
  FuzzStepIo step_io_, started_step_io_;
  TickIo tick_io_{&step_io_}, started_tick_io_{&step_io_};
  std::vector<uint8_t> started_tables_, started_settings_;
  alignas(App) unsigned char app_[sizeof(App)];
  alignas(App) unsigned char started_app_[sizeof(App)];
};
static_assert(std::is_trivially_destructible_v<App>, "a board copied over must own nothing");

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static Rig* rig = new Rig();  // for the whole run (never freed: no teardown order to get wrong)
  static uint64_t runs = 0;
  const uint64_t digest = rig->Run(data, size);
  if (runs++ % kRecheckEvery == 0 && rig->Run(data, size) != digest) std::abort();
  return 0;
}
