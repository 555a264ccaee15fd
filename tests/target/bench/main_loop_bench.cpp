// Main-loop cycle bench (QEMU mps2-an386): the board application's main loop receiving a table by
// SDO block download (CiA 301), one frame per pass, as on the STM32G474 reference board (polled
// FDCAN receive FIFO: docs/mcu-target.md, "Main loop under the tick"). The image links every
// function into the traced range (mps2_an386.ld with bench-extra-hot.ld from hot-extra/all), and
// toolchain/cyclemodel/cm4cost.py prices each pass from the trace (--trace-only: the main loop has
// virtual calls, so it has no static bound). Rows, each one call of its wrapper per pass:
//   main_loop_segment  a pass that receives one block segment (the FIFO's per-frame path: node,
//                      SDO server with its CRC-16, board objects, the table store's buffer)
//   main_loop_pass     a pass that receives nothing (while the server holds a sub-block's
//                      acknowledgement: one flush step of the store, programming or a page erase)
//   main_loop_request  a pass that receives any other request (expedited writes, block initiate
//                      and end)
// The whole download runs once per row (each after its scenario mark), first in NMT
// pre-operational (as during a table upload), then again in operational (main_loop_op_*: the same
// passes plus the TPDOs, sampled and sent every pass they are due); the image exits non-zero if a
// download does not complete, so a row never prices a broken transfer. Last, in operational:
//   main_loop_op_rpdo  a pass that receives RPDO1 (the command word 0x2127): every other one
//                      raises activate, refused (nothing verified is staged) with its EMCY
// Then, with a thermal model active (all 8 channels written over CAN, every axis with an offset
// and a slope on every channel, a slew limit low enough that the correction always slews):
//   main_loop_thermal  a pass in which the thermal period is due (supervision, the model's update,
//                      the terms in steps, their hand-over) and which receives a temperature
//                      write (0x2150:n) and sends the TPDOs: the thermal pass at its worst
// Last, the board-local sensors (the STM32 image's main loop: TemperatureAdc and
// AdcTemperatureInputs, docs/thermal.md "Board-local sensors"), after a node reset that makes
// channels 1-2 NTCs and 3-4 PT1000s on the ADC inputs (5-8 stay CAN objects):
//   main_loop_adc_scan        main()'s step beside Poll() when a scan is due: the driver collects
//                             JDR1-4 and starts the next scan (its registers in RAM here), the
//                             four averagers take the scan; every 50th completes the windows
//   main_loop_thermal_sensors the thermal pass with the inputs' readings as they come (10 scans
//                             per period; the windows are staggered, so at most one conversion
//                             per pass: NTC or PT1000), a temperature write and the TPDOs
#include <cstdint>

#include "bench_support.hpp"
#include "cases.hpp"
#include "semihost.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/firmware/adc_temperature_inputs.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/stm32g4/drivers.hpp"
#include "volcomp/hal/stm32g4/temperature_adc.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::target {
namespace {

// The bus side of FDCAN1: one received frame at a time (the bench delivers one per pass), sent
// frames collected for the client.
class BenchCan final : public hal::CanPort {
 public:
  void Deliver(const CanFrame& f) {
    rx_ = f;
    have_rx_ = true;
  }
  uint32_t other_sent() const { return other_sent_; }
  bool TakeSent(CanFrame* f) {
    if (sent_count_ == 0) return false;
    *f = sent_[0];
    for (uint32_t i = 1; i < sent_count_; ++i) sent_[i - 1] = sent_[i];
    --sent_count_;
    return true;
  }

 private:
  Status DoSend(const CanFrame& frame) override {
    // The client reads only the SDO responses; the rest (heartbeat, TPDOs, EMCY) is counted.
    if (frame.id != 0x580u + canopen::kDefaultNodeId) {
      ++other_sent_;
      return Status::Ok();
    }
    if (sent_count_ == kSent) return Error::kFull;
    sent_[sent_count_++] = frame;
    return Status::Ok();
  }
  bool DoReceive(CanFrame* frame) override {
    if (!have_rx_) return false;
    *frame = rx_;
    have_rx_ = false;
    return true;
  }
  Status DoSetBitrate(uint32_t) override { return Status::Ok(); }
  static constexpr uint32_t kSent = 8;
  CanFrame rx_;
  bool have_rx_ = false;
  CanFrame sent_[kSent];
  uint32_t sent_count_ = 0;
  uint32_t other_sent_ = 0;
};

// Time advances one frame time (111 us at 1 Mbit/s) per pass.
class BenchClock final : public hal::Clock {
 public:
  void Advance(uint64_t ns) { now_ns_ += ns; }

 private:
  uint64_t DoNowNs() override { return now_ns_; }
  uint64_t now_ns_ = 0;
};

stm32g4::StepIo g_step_io;
BenchIo g_io(&g_step_io);
BenchLines g_lines;  // never homed
BenchFlash g_flash;
BenchCan g_can;
BenchClock g_clock;
firmware::AdcTemperatureInputs g_sensors;
BenchApp g_app({&g_io, &g_lines, &g_flash, nullptr, &g_can, &g_clock, nullptr, &g_sensors});

// The temperature ADC's registers in RAM (ADC2's block from 0x50000100 and what the bring-up
// touches around it), and a cycle counter the bench sets.
uint32_t g_adc_regs[64];
uint32_t g_adc_cycles = 0;
struct BenchAdcBus {
  static uint32_t* Word(uintptr_t a) {
    const uintptr_t i = (a - stm32g4::kAdc2Base) / 4u;
    return i < 64 ? &g_adc_regs[i] : &g_adc_regs[63];  // RCC, GPIO, CCR: a scratch word
  }
  static uint32_t Read(uintptr_t a) { return *static_cast<volatile uint32_t*>(Word(a)); }
  static void Write(uintptr_t a, uint32_t v) {
    *static_cast<volatile uint32_t*>(Word(a)) = v;
    if (a == stm32g4::kAdc2Base + stm32g4::adc::kCr) {  // calibration done, ready at once
      g_adc_regs[stm32g4::adc::kCr / 4] &= ~stm32g4::adc::kCrAdcal;
      if ((v & stm32g4::adc::kCrAden) != 0) g_adc_regs[0] |= stm32g4::adc::kIsrAdrdy;
    }
  }
  static uint32_t Cycles() { return g_adc_cycles += 1000; }
};
stm32g4::TemperatureAdc<BenchAdcBus> g_adc;
// The payload: a table image followed by filler, 6000 bytes (more than the store takes between
// flushes, 1017 bytes, and across 2 KB pages: the download runs flush steps, programming and
// erases, between its sub-blocks). Staging checks no content before verification.
constexpr uint32_t kPayloadBytes = 6000;
static_assert(kPayloadBytes >= kMaxCaseImage, "the payload starts with a whole table image");
alignas(8) uint8_t g_image[kPayloadBytes];

}  // namespace
}  // namespace volcomp::target

// One main-loop pass per call, by what it received (the rows above).
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_segment"))) void
volcomp_bench_poll_segment() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_pass"))) void
volcomp_bench_poll_pass() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_request"))) void
volcomp_bench_poll_request() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_op_segment"))) void
volcomp_bench_poll_op_segment() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_op_pass"))) void
volcomp_bench_poll_op_pass() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_op_request"))) void
volcomp_bench_poll_op_request() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_op_rpdo"))) void
volcomp_bench_poll_op_rpdo() {
  volcomp::target::g_app.Poll();
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_poll_thermal"))) void
volcomp_bench_poll_thermal() {
  volcomp::target::g_app.Poll();
}
// As in firmware/stm32g4/main.cpp's loop.
extern "C" __attribute__((noinline, section(".text.volcomp_bench_adc_scan"))) void
volcomp_bench_adc_scan() {
  uint16_t counts[volcomp::firmware::kAdcSensorInputs];
  if (volcomp::target::g_adc.Poll(counts)) volcomp::target::g_sensors.AddScan(counts);
}
extern "C" __attribute__((noinline, section(".text.volcomp_bench_sensors_poll"))) void
volcomp_bench_sensors_poll() {
  volcomp::target::g_app.Poll();
}

namespace volcomp::target {
namespace {

constexpr uint8_t kNode = canopen::kDefaultNodeId;
constexpr uint64_t kFrameNs = 111000;

// CRC-16/XMODEM (CiA 301 block transfer), bit by bit.
uint16_t Crc16(const uint8_t* d, uint32_t n) {
  uint16_t crc = 0;
  for (uint32_t i = 0; i < n; ++i) {
    crc = static_cast<uint16_t>(crc ^ (d[i] << 8));
    for (int k = 0; k < 8; ++k) {
      crc = static_cast<uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
  }
  return crc;
}

CanFrame Request() {
  CanFrame f;
  f.id = 0x600u + kNode;
  f.dlc = 8;
  return f;
}

CanFrame ExpeditedWrite(uint16_t index, uint32_t value, uint8_t bytes) {
  CanFrame f = Request();
  f.data[0] = static_cast<uint8_t>(0x23 | ((4 - bytes) << 2));  // expedited, size indicated
  f.data[1] = static_cast<uint8_t>(index);
  f.data[2] = static_cast<uint8_t>(index >> 8);
  for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(value >> (8 * i));
  return f;
}

enum class Pass { kSegment, kNothing, kRequest };
bool g_operational = false;  // which rows the passes belong to

void RunPass(Pass p) {
  g_clock.Advance(kFrameNs);
  if (p == Pass::kSegment)
    (g_operational ? volcomp_bench_poll_op_segment : volcomp_bench_poll_segment)();
  if (p == Pass::kNothing) (g_operational ? volcomp_bench_poll_op_pass : volcomp_bench_poll_pass)();
  if (p == Pass::kRequest)
    (g_operational ? volcomp_bench_poll_op_request : volcomp_bench_poll_request)();
}

// Sends `f` and runs passes until the server answers (at most `limit` passes); returns the answer
// (data[0] == 0x80 for an abort, 0 when none came).
CanFrame Transact(const CanFrame* f, Pass kind, uint32_t limit) {
  if (f != nullptr) g_can.Deliver(*f);
  RunPass(kind);
  for (uint32_t i = 0;; ++i) {
    CanFrame r;
    while (g_can.TakeSent(&r)) {
      if (r.id == 0x580u + kNode) return r;
    }
    if (i == limit) return CanFrame();
    RunPass(Pass::kNothing);
  }
}

// One block download of g_image[0, size) into 0x2100:0 after unlocking and clearing the staging
// bank; true when the server confirmed its end.
bool Download(uint32_t size) {
  CanFrame f = ExpeditedWrite(0x2110, canopen::kUnlockSignature, 4);
  if (Transact(&f, Pass::kRequest, 100).data[0] != 0x60) return false;
  f = ExpeditedWrite(0x2101, static_cast<uint32_t>(canopen::TableCommand::kClear), 1);
  if (Transact(&f, Pass::kRequest, 10000).data[0] != 0x60) return false;
  f = Request();
  f.data[0] = 0xC6;  // block download initiate: CRC supported, size indicated
  f.data[1] = 0x00;
  f.data[2] = 0x21;  // 0x2100:0
  for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(size >> (8 * i));
  CanFrame r = Transact(&f, Pass::kRequest, 100);
  if ((r.data[0] & 0xE3) != 0xA0) return false;
  uint32_t blksize = r.data[4], pos = 0, last_len = 0;
  while (pos < size) {
    uint32_t seq = 0;
    r = CanFrame();
    while (seq < blksize && pos < size) {
      CanFrame s = Request();
      const uint32_t n = size - pos < 7 ? size - pos : 7;
      ++seq;
      s.data[0] = static_cast<uint8_t>(seq | (pos + n == size ? 0x80u : 0u));
      for (uint32_t i = 0; i < n; ++i) s.data[1 + i] = g_image[pos + i];
      pos += n;
      last_len = n;
      const bool block_end = seq == blksize || pos == size;
      if (!block_end) {
        g_can.Deliver(s);
        RunPass(Pass::kSegment);
        continue;
      }
      r = Transact(&s, Pass::kSegment, 100000);  // the ack may wait for the paced programming
    }
    if (r.data[0] != 0xA2 || r.data[1] != seq || r.data[2] == 0) return false;
    blksize = r.data[2];
    RunPass(Pass::kNothing);  // the bus gap before the client's next sub-block
  }
  f = Request();
  f.data[0] = static_cast<uint8_t>(0xC1 | ((7 - last_len) << 2));
  const uint16_t crc = Crc16(g_image, size);
  f.data[1] = static_cast<uint8_t>(crc);
  f.data[2] = static_cast<uint8_t>(crc >> 8);
  r = Transact(&f, Pass::kRequest, 100000);
  return r.data[0] == 0xA1;
}

// One thermal pass through `poll`: a temperature write to channel `ch` (0-based) received, a
// thermal period of the bench's clock passed, the frames sent drained.
void ThermalPass(uint8_t ch, uint32_t i, void (*poll)()) {
  CanFrame w = ExpeditedWrite(0x2150, 2300u + i % 7u + ch, 2);
  w.data[3] = static_cast<uint8_t>(ch + 1);
  g_can.Deliver(w);
  g_clock.Advance(firmware::kThermalPeriodMs * 1000000ull);
  poll();
  CanFrame r;
  while (g_can.TakeSent(&r)) {
  }
}
// The model runs on valid channels: active, not holding, slewing.
bool ThermalModelRunning() {
  const thermal::ThermalStatus& ts = g_app.thermal().correction().status();
  return ts.active && !ts.holding && ts.slewing && g_app.thermal().channel_fault_mask() == 0;
}
CanFrame NmtStart() {
  CanFrame start;
  start.id = 0x000;
  start.dlc = 2;
  start.data[0] = 0x01;
  start.data[1] = kNode;
  return start;
}

// An image of the board's axes with a thermal model only (AXES + THERMAL): every axis with an
// offset and a slope on all 8 channels (T_ref 20 C, calibrated 0..60 C), slew 0.05 um/s.
alignas(8) uint8_t g_thermal_image[1024];
uint32_t BuildThermalImage(const BoardConfig& cfg) {
  static thermal::ThermalModel m;
  m.axis_count = cfg.axis_count;
  m.channel_mask = 0xFF;
  m.slew_um_s = 0.05f;
  for (uint8_t j = 0; j < thermal::kMaxChannels; ++j) {
    m.reference_cC[j] = 2000;
    m.calibrated_low_cC[j] = 0;
    m.calibrated_high_cC[j] = 6000;
  }
  table::ImageSpec spec;
  spec.table_id = 5;
  spec.axis_count = cfg.axis_count;
  for (uint8_t a = 0; a < cfg.axis_count; ++a) {
    spec.axes[a] = {cfg.axis[a].name, cfg.axis[a].kind, cfg.axis[a].resolution_e9};
    if (cfg.axis[a].kind != table::AxisKind::kLinear) continue;
    m.axis[a].reach_mm = 500.0f;
    for (uint8_t j = 0; j < thermal::kMaxChannels; ++j) {
      m.axis[a].offset_um_per_K[j] = 0.5f + 0.1f * j;
      m.axis[a].slope_um_per_K_m[j] = -2.0f + 0.5f * j;
    }
  }
  spec.thermal = &m;
  const Result<uint32_t> n = table::WriteImage(spec, g_thermal_image, sizeof g_thermal_image);
  return n.ok() ? *n : 0;
}

}  // namespace
}  // namespace volcomp::target

int main() {
  using namespace volcomp;
  using namespace volcomp::target;
  BoardConfig cfg = TickBoardConfig();
  for (uint8_t a = 0; a < stm32g4::kStepAxes; ++a) {
    cfg.axis[a].input_counter_bits = stm32g4::kInputCounterBits[a];
  }
  firmware::AppOptions options;
  options.use_enable_input = false;
  const uint32_t image = BuildTickImage(g_image, sizeof g_image);
  for (uint32_t i = image; i < kPayloadBytes; ++i) g_image[i] = static_cast<uint8_t>(i * 7u);
  const uint32_t size = kPayloadBytes;
  BoardSettings settings;
  settings.board = cfg;
  for (thermal::ChannelConfig& c : settings.temperature)
    c.source = thermal::ChannelSource::kCanObject;
  if (image == 0 || !g_app.Start(settings, options).ok()) {
    semihost::Write("bench: main-loop board setup failed\n");
    return 1;
  }
  semihost::Write("bench: download of ");
  semihost::WriteUint(size);
  semihost::Write(" bytes (a table image of ");
  semihost::WriteUint(image);
  semihost::Write(" bytes first)\n");
  struct Row {
    const char* name;
    const char* symbol;
    bool operational;  // NMT start before the row's download
  };
  const Row kRows[] = {
      {"main_loop_segment", "volcomp_bench_poll_segment", false},
      {"main_loop_pass", "volcomp_bench_poll_pass", false},
      {"main_loop_request", "volcomp_bench_poll_request", false},
      {"main_loop_op_segment", "volcomp_bench_poll_op_segment", true},
      {"main_loop_op_pass", "volcomp_bench_poll_op_pass", true},
      {"main_loop_op_request", "volcomp_bench_poll_op_request", true},
  };
  int rc = 0;
  for (const auto& row : kRows) {
    if (row.operational && !g_operational) {
      g_can.Deliver(NmtStart());
      RunPass(Pass::kNothing);
      g_operational = true;
      if (g_app.node().state() != canopen::NmtState::kOperational) rc = 1;
    }
    Scenario(row.name, row.symbol);
    if (!Download(size)) {
      semihost::Write("bench: block download did not complete\n");
      rc = 1;
    }
  }
  if (g_app.tables().staged_bytes() != size) rc = 1;
  // The RPDO: 200 passes, each receiving the command word; activate rises every other one.
  Scenario("main_loop_op_rpdo", "volcomp_bench_poll_op_rpdo");
  const uint32_t refused = g_app.objects().refused_actions();
  for (uint32_t i = 0; i < 200; ++i) {
    CanFrame rpdo;
    rpdo.id = 0x200u + kNode;
    rpdo.dlc = 2;
    rpdo.data[1] = static_cast<uint8_t>((i & 1u) == 0 ? canopen::kCommandActivate >> 8 : 0);
    g_can.Deliver(rpdo);
    g_clock.Advance(kFrameNs);
    volcomp_bench_poll_op_rpdo();
  }
  if (g_app.node().rpdo_received() != 200 || g_app.objects().refused_actions() != refused + 100) {
    semihost::Write("bench: the RPDO passes did not act as expected\n");
    rc = 1;
  }
  // The thermal passes: the model active, every channel written once per 800 ms (valid), each pass
  // a thermal period (100 ms).
  const uint32_t thermal_image = BuildThermalImage(cfg);
  if (thermal_image == 0 || !g_app.ActivateImage(g_thermal_image, thermal_image).ok()) {
    semihost::Write("bench: the thermal image was not activated\n");
    rc = 1;
  }
  Scenario("main_loop_thermal", "volcomp_bench_poll_thermal");
  for (uint32_t i = 0; i < 100; ++i)
    ThermalPass(static_cast<uint8_t>(i % thermal::kMaxChannels), i, volcomp_bench_poll_thermal);
  if (!ThermalModelRunning()) {
    semihost::Write("bench: the thermal passes did not run the model (active, valid, slewing)\n");
    rc = 1;
  }
  // The board-local sensors: a node reset with channels 1-4 on the ADC inputs, the model again.
  settings.temperature[0].source = thermal::ChannelSource::kBoardNtc;
  settings.temperature[1].source = thermal::ChannelSource::kBoardNtc;
  settings.temperature[2].source = thermal::ChannelSource::kBoardPt1000;
  settings.temperature[3].source = thermal::ChannelSource::kBoardPt1000;
  if (!g_app.Start(settings, options).ok() ||
      !g_app.ActivateImage(g_thermal_image, thermal_image).ok()) {
    semihost::Write("bench: the sensor board did not start\n");
    rc = 1;
  }
  g_can.Deliver(NmtStart());
  volcomp_bench_sensors_poll();
  // Inputs at 24.5 C (NTC: 10.2 kOhm ... ) and 21 C (PT1000 1081.7 Ohm): counts = 65536 R / (R +
  // 10 k), the ADC's JDR1-4 (JEOS set: every due call collects).
  g_adc.Start();
  g_adc_regs[0x80 / 4 + 0] = g_adc_regs[0x80 / 4 + 1] = 33096;  // 10.2 kOhm
  g_adc_regs[0x80 / 4 + 2] = g_adc_regs[0x80 / 4 + 3] = 6394;   // 1081.7 Ohm
  Scenario("main_loop_adc_scan", "volcomp_bench_adc_scan");
  for (uint32_t i = 0; i < 200; ++i) {
    g_adc_regs[0] |= stm32g4::adc::kIsrJeos;
    g_adc_cycles += stm32g4::kTemperatureScanPeriodCycles;
    volcomp_bench_adc_scan();
  }
  Scenario("main_loop_thermal_sensors", "volcomp_bench_sensors_poll");
  for (uint32_t i = 0; i < 100; ++i) {
    uint16_t counts[firmware::kAdcSensorInputs] = {33096, 33100, 6394, 6398};
    counts[i % 4] = static_cast<uint16_t>(counts[i % 4] + i % 3);  // noise
    for (uint32_t k = 0; k < 10; ++k) g_sensors.AddScan(counts);   // 100 ms of scans
    ThermalPass(static_cast<uint8_t>(4 + i % 4), i, volcomp_bench_sensors_poll);
  }
  if (!ThermalModelRunning() ||
      g_app.thermal().channels().state(0) != thermal::ChannelState::kValid ||
      g_app.thermal().channels().state(3) != thermal::ChannelState::kValid) {
    semihost::Write("bench: the sensor passes did not run the model on valid ADC channels\n");
    rc = 1;
  }
  semihost::Write("bench: frames other than SDO responses sent: ");
  semihost::WriteUint(g_can.other_sent());
  semihost::Write("\n");
  semihost::Write(rc == 0 ? "bench: done\n" : "bench: FAILED\n");
  return rc;
}
