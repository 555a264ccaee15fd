// SDO block download into the table store at 1 Mbit/s, frame by frame in virtual time, with the
// STM32G474's constraints (docs/mcu-target.md, "Main loop under the tick: SDO block download"):
//   bus       every frame 111 bit times (8 data bytes, standard id, no stuff bits: the shortest,
//             i.e. the fastest arrival), one after the other;
//   receiver  a 3-frame receive FIFO (FDCAN Rx FIFO 0, blocking mode: a frame that completes
//             while it is full is lost), drained by a main loop whose passes cost CPU time, at the
//             share of the CPU the tick interrupt leaves at its static worst;
//   flash     every erase and program takes the datasheet's maximum time, during which the main
//             loop does nothing else (it waits for BSY).
// The client is written here from CiA 301 (block download with CRC), not the project's client.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/canopen/sdo_server.hpp"
#include "volcomp/firmware/table_store.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"

namespace volcomp {
namespace {

using canopen::SdoAbort;

// ---- Figures (docs/mcu-target.md states where each comes from) ----
constexpr uint64_t kFrameNs = 111000;  // 47 + 64 bits at 1 Mbit/s, no stuff bits
// Main loop CPU cycles (Cortex-M4 model, rows of tests/target main_loop_cycles: the traced worst
// pass of an SDO block download on the firmware's own main loop, node and board objects included,
// rounded up): a pass with nothing to do (main_loop_pass without a flush step, 981), a pass that
// receives a segment (main_loop_segment 3571: the worst is a sub-block's last segment, whose pass
// also runs the first flush step, and a thermal period), a pass with a flush step (main_loop_pass
// 5053: a page erase). Each figure includes the pass itself, which the test adds again:
// conservative. Every 100 ms one pass also runs the thermal period with a model on all 8 channels
// (main_loop_thermal_sensors 12425: four of them on the board's ADC inputs, one reading converted;
// with a request received and the TPDOs sent), charged on top; and every 10 ms the STM32 main
// loop collects an ADC scan of the temperature inputs (main_loop_adc_scan 524).
struct Costs {
  uint64_t pass;     // a pass with nothing received
  uint64_t segment;  // one block segment received and delivered
  uint64_t flush;    // one flush step's CPU work, without the flash wait
};
constexpr Costs kPreOperational = {1000, 3600, 5100};
constexpr uint64_t kThermalPassCycles = 12500, kThermalPeriodNs = 100000000;
constexpr uint64_t kAdcScanCycles = 530, kAdcScanPeriodNs = 10000000;
// In NMT operational the TPDOs are sampled and sent when due (rows main_loop_op_*): the worst
// segment pass 7879 (a TPDO pass on top of a segment), rounded up; every pass charged the worst
// TPDO work (op rows' worst minus the pre-operational rows', about 4160: both TPDOs sampled and
// sent), although they leave at most twice per 21 ms inhibit time: conservative.
constexpr Costs kOperational = {1000 + 4200, 7900, 5100};
Costs g_costs = kPreOperational;  // of the run in progress
// The CPU share the interrupts leave at their static worst: 3400 cycles a period at 50 kHz, of
// them the tick 948 (tick_isr_3axes) and a third of the compensation run's 1168 (every third
// tick, compensation_isr_3axes): 1340 per period, rounded up.
constexpr uint64_t kPeriodCycles = 3400, kTickCycles = 1340;
constexpr uint64_t kSysclkMhz = 170;
// STM32G474 flash (datasheet DS12288, flash memory characteristics, maximum): 64-bit
// programming 90.76 us, 2 KB page erase 24.47 ms.
constexpr uint64_t kProgramNs = 90760, kEraseNs = 24470000;

uint64_t CpuNs(uint64_t cycles) {
  // Cycles the main loop gets per period: kPeriodCycles - kTickCycles.
  return cycles * kPeriodCycles * 1000 / ((kPeriodCycles - kTickCycles) * kSysclkMhz);
}

// CRC-16/XMODEM, bit by bit (CiA 301 block transfer CRC: polynomial 0x1021, initial 0).
uint16_t Crc16(const std::vector<uint8_t>& d) {
  uint16_t crc = 0;
  for (uint8_t b : d) {
    crc = static_cast<uint16_t>(crc ^ (b << 8));
    for (int k = 0; k < 8; ++k) {
      crc = static_cast<uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
  }
  return crc;
}

/// Flash whose every operation takes its busy time on the shared clock.
class TimedFlash : public hal::Flash {
 public:
  TimedFlash(hal::mock::MockClock* clock)
      : clock_(clock), inner_(128 * 1024, 2048, 8, clock, nullptr) {}
  uint32_t erases() const { return inner_.erase_count(); }
  uint32_t programs() const { return inner_.program_count(); }
  hal::mock::MockFlash& inner() { return inner_; }

 private:
  uint32_t DoSize() const override { return inner_.size(); }
  uint32_t DoSectorSize() const override { return inner_.sector_size(); }
  uint32_t DoProgramUnit() const override { return inner_.program_unit(); }
  Status DoErase(uint32_t offset) override {
    clock_->Advance(kEraseNs);
    return inner_.Erase(offset);
  }
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override {
    clock_->Advance(kProgramNs * (bytes / 8));
    return inner_.Program(offset, data, bytes);
  }
  const uint8_t* DoMap(uint32_t offset) const override { return inner_.Map(offset); }

  hal::mock::MockClock* clock_;
  hal::mock::MockFlash inner_;
};

/// The table object as the board serves it, with the pacing it asks for (or none: the store
/// programs each double-word as it completes, in the receive path).
class TableValue : public canopen::ObjectValues {
 public:
  TableValue(firmware::TableStore* store,
             hal::mock::MockClock* clock,
             bool paced,
             uint32_t window = 0)
      : store_(store), clock_(clock), paced_(paced), window_(window) {}

 private:
  SdoAbort DoRead(const canopen::ObjectEntry&,
                  uint32_t,
                  uint8_t*,
                  uint32_t,
                  uint32_t* copied,
                  uint32_t* total) override {
    *copied = *total = 0;
    return SdoAbort::kNone;
  }
  SdoAbort DoWrite(const canopen::ObjectEntry&, const uint8_t*, uint32_t) override {
    return SdoAbort::kReadOnly;
  }
  SdoAbort DoBeginDomainWrite(const canopen::ObjectEntry&, uint32_t size) override {
    return store_->BeginUpload(size).ok() ? SdoAbort::kNone : SdoAbort::kHardware;
  }
  SdoAbort DoDomainWriteData(const uint8_t* data, uint32_t size) override {
    clock_->Advance(CpuNs(g_costs.segment));
    if (!store_->UploadData(data, size).ok()) return SdoAbort::kHardware;
    if (paced_) return SdoAbort::kNone;
    for (bool done = false; !done;) {
      if (!store_->FlushUpload(&done).ok()) return SdoAbort::kHardware;
    }
    return SdoAbort::kNone;
  }
  SdoAbort DoEndDomainWrite(SdoAbort outcome, canopen::AbortOrigin) override {
    if (canopen::Failed(outcome)) {
      store_->AbandonUpload(Error::kTransferAborted);
      return SdoAbort::kNone;
    }
    return store_->FinishUpload().ok() ? SdoAbort::kNone : SdoAbort::kHardware;
  }
  uint32_t DoDomainWriteWindow() override {
    if (!paced_) return 0;
    return window_ != 0 ? window_ : store_->upload_window();
  }
  SdoAbort DoDomainWriteFlush(bool* done) override {
    clock_->Advance(CpuNs(g_costs.flush));
    return store_->FlushUpload(done).ok() ? SdoAbort::kNone : SdoAbort::kHardware;
  }

  firmware::TableStore* store_;
  hal::mock::MockClock* clock_;
  bool paced_;
  uint32_t window_;
};

constexpr uint8_t kNode = 5;

/// The bus, the receive FIFO and a CiA 301 block download client, in virtual time.
class BlockDownloadRun {
 public:
  BlockDownloadRun(hal::mock::MockClock* clock, std::vector<uint8_t> data)
      : clock_(clock), data_(std::move(data)) {}

  // ---- the server's side of the port ----
  bool Receive(CanFrame* f) {
    Arrive();
    if (fifo_.empty()) return false;
    *f = fifo_.front();
    fifo_.pop_front();
    return true;
  }
  void Send(const CanFrame& f) {
    const uint64_t done = OnBus();
    ClientSees(f, done);
  }

  // ---- the client ----
  void Start() {
    CanFrame f = Request();
    f.data[0] = 0xC6;  // block download initiate, CRC, size indicated
    f.data[1] = 0x00;
    f.data[2] = 0x21;  // 0x2100:0
    for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(data_.size() >> (8 * i));
    Put(f, clock_->now());
  }
  bool finished() const { return finished_; }
  uint32_t lost() const { return lost_; }
  size_t max_fill() const { return max_fill_; }
  const std::vector<uint8_t>& block_sizes() const { return blksizes_; }
  uint32_t resent() const { return resent_; }

 private:
  CanFrame Request() const {
    CanFrame f;
    f.id = 0x600 + kNode;
    f.dlc = 8;
    return f;
  }
  // Queues a client frame on the bus no earlier than `t`.
  void Put(const CanFrame& f, uint64_t t) {
    if (bus_free_ < t) bus_free_ = t;
    bus_free_ += kFrameNs;
    in_flight_.push_back({bus_free_, f});
  }
  uint64_t OnBus() {
    if (bus_free_ < clock_->now()) bus_free_ = clock_->now();
    bus_free_ += kFrameNs;
    return bus_free_;
  }
  // Client frames whose last bit has passed enter the FIFO in order; a full FIFO loses them.
  void Arrive() {
    while (!in_flight_.empty() && in_flight_.front().first <= clock_->now()) {
      if (fifo_.size() == 3) {
        ++lost_;
      } else {
        fifo_.push_back(in_flight_.front().second);
        if (fifo_.size() > max_fill_) max_fill_ = fifo_.size();
      }
      in_flight_.pop_front();
    }
  }
  void SendSubBlock(uint64_t t) {
    uint8_t seq = 0;
    while (seq < blksize_ && pos_ + seq * 7u < data_.size()) {
      ++seq;
      const size_t at = pos_ + (seq - 1u) * 7u;
      CanFrame f = Request();
      const bool last = at + 7 >= data_.size();
      f.data[0] = static_cast<uint8_t>(seq | (last ? 0x80 : 0));
      for (size_t i = 0; i < 7 && at + i < data_.size(); ++i) f.data[1 + i] = data_[at + i];
      Put(f, t);
      if (last) break;
    }
    sent_in_block_ = seq;
  }
  void ClientSees(const CanFrame& r, uint64_t t) {
    const uint8_t cmd = r.data[0];
    ASSERT_EQ(r.id, 0x580u + kNode);
    ASSERT_NE(cmd, 0x80) << "abort " << std::hex << (r.data[4] | r.data[5] << 8 | r.data[6] << 16);
    if ((cmd & 0xE3) == 0xA0) {  // initiate response
      blksize_ = r.data[4];
      blksizes_.push_back(blksize_);
      SendSubBlock(t);
    } else if (cmd == 0xA2) {  // sub-block acknowledgement
      const uint8_t ackseq = r.data[1];
      blksize_ = r.data[2];
      blksizes_.push_back(blksize_);
      resent_ += sent_in_block_ - ackseq;
      pos_ = std::min(data_.size(), pos_ + ackseq * 7u);
      if (pos_ < data_.size()) return SendSubBlock(t);
      CanFrame f = Request();
      const uint32_t unused = static_cast<uint32_t>((7 - data_.size() % 7) % 7);
      f.data[0] = static_cast<uint8_t>(0xC1 | (unused << 2));
      const uint16_t crc = Crc16(data_);
      f.data[1] = static_cast<uint8_t>(crc);
      f.data[2] = static_cast<uint8_t>(crc >> 8);
      Put(f, t);
    } else if (cmd == 0xA1) {  // end response
      finished_ = true;
    } else {
      FAIL() << "unexpected response " << std::hex << int{cmd};
    }
  }

  hal::mock::MockClock* clock_;
  std::vector<uint8_t> data_;
  std::deque<std::pair<uint64_t, CanFrame>> in_flight_;  // completion time, frame
  std::deque<CanFrame> fifo_;
  uint64_t bus_free_ = 0;
  size_t pos_ = 0;
  uint8_t blksize_ = 0;
  uint8_t sent_in_block_ = 0;
  bool finished_ = false;
  uint32_t lost_ = 0;
  size_t max_fill_ = 0;
  uint32_t resent_ = 0;
  std::vector<uint8_t> blksizes_;
};

struct Outcome {
  bool finished;
  uint32_t lost;
  size_t max_fill;
  std::vector<uint8_t> blksizes;
  uint32_t resent;
  double seconds;
  bool staged_intact;
};

Outcome Download(bool paced, uint32_t window, size_t bytes, const Costs& costs = kPreOperational) {
  g_costs = costs;
  hal::mock::MockClock clock;
  TimedFlash flash(&clock);
  firmware::TableStore store;
  EXPECT_TRUE(store.Init(&flash, flash.size() / 2).ok());
  TableValue value(&store, &clock, paced, window);
  canopen::SdoServer server;
  server.Init(kNode, &value);
  std::mt19937 rng(7);
  std::vector<uint8_t> data(bytes);
  for (auto& b : data) b = static_cast<uint8_t>(rng());
  BlockDownloadRun run(&clock, data);
  run.Start();
  // The main loop: drain the FIFO, run the server's timers (and flush steps), send; every 100 ms a
  // pass also runs the thermal period, every 10 ms one collects an ADC scan.
  uint64_t next_thermal_ns = kThermalPeriodNs, next_scan_ns = kAdcScanPeriodNs;
  while (!run.finished() && clock.now() < 60'000'000'000ull) {
    const uint32_t now_ms = static_cast<uint32_t>(clock.now() / 1000000);
    CanFrame f;
    while (run.Receive(&f)) server.OnFrame(f, now_ms);
    server.Poll(now_ms);
    while (server.PopTx(&f)) run.Send(f);
    clock.Advance(CpuNs(g_costs.pass));
    if (clock.now() >= next_thermal_ns) {
      clock.Advance(CpuNs(kThermalPassCycles));
      next_thermal_ns += kThermalPeriodNs;
    }
    if (clock.now() >= next_scan_ns) {
      clock.Advance(CpuNs(kAdcScanCycles));
      next_scan_ns += kAdcScanPeriodNs;
    }
    if (::testing::Test::HasFatalFailure()) break;
  }
  bool same = store.staged_state() == canopen::StagedState::kComplete &&
              store.staged_bytes() == bytes && store.staged_data() != nullptr;
  for (size_t i = 0; same && i < bytes; ++i) same = store.staged_data()[i] == data[i];
  return {run.finished(),
          run.lost(),
          run.max_fill(),
          run.block_sizes(),
          run.resent(),
          static_cast<double>(clock.now()) / 1e9,
          same};
}

constexpr size_t kImageBytes = 40000;  // about 45 sub-blocks of 127 segments, 20 page erases

TEST(SdoBlockPacing, PacedDownloadLosesNoFrameAt1Mbit) {
  const Outcome o = Download(/*paced=*/true, 0, kImageBytes);
  ASSERT_TRUE(o.finished);
  EXPECT_EQ(o.lost, 0u);
  EXPECT_EQ(o.resent, 0u);
  EXPECT_LE(o.max_fill, 3u);
  EXPECT_TRUE(o.staged_intact);
  // The store's 1 KB buffer takes a whole sub-block of 127 segments (889 bytes).
  for (uint8_t b : o.blksizes) EXPECT_EQ(b, 127);
  std::printf("paced: %zu bytes in %.3f s (%.1f kB/s), FIFO fill at most %zu, 0 lost\n",
              kImageBytes, o.seconds, kImageBytes / o.seconds / 1000, o.max_fill);
}

TEST(SdoBlockPacing, PacedDownloadInOperationalLosesNoFrame) {
  // The same with the TPDOs' cost on every pass (a master may upload in operational).
  const Outcome o = Download(/*paced=*/true, 0, kImageBytes, kOperational);
  ASSERT_TRUE(o.finished);
  EXPECT_EQ(o.lost, 0u);
  EXPECT_EQ(o.resent, 0u);
  EXPECT_LE(o.max_fill, 3u);
  EXPECT_TRUE(o.staged_intact);
  std::printf("paced, operational costs: %.3f s (%.1f kB/s), FIFO fill at most %zu, 0 lost\n",
              o.seconds, kImageBytes / o.seconds / 1000, o.max_fill);
}

TEST(SdoBlockPacing, BlockSizeFollowsTheValuesWindow) {
  // A value that buffers 300 bytes: 42 segments a sub-block, still nothing lost.
  const Outcome o = Download(/*paced=*/true, 300, kImageBytes);
  ASSERT_TRUE(o.finished);
  EXPECT_EQ(o.lost, 0u);
  EXPECT_TRUE(o.staged_intact);
  ASSERT_FALSE(o.blksizes.empty());
  for (uint8_t b : o.blksizes) EXPECT_EQ(b, 300 / 7);
  std::printf("window 300 B: blksize %d, %.3f s (%.1f kB/s)\n", int{o.blksizes[0]}, o.seconds,
              kImageBytes / o.seconds / 1000);
}

TEST(SdoBlockPacing, ProgrammingInTheReceivePathOverflowsTheFifo) {
  // Without pacing the store programs while segments keep arriving: the FIFO overflows, the
  // server acknowledges the gaps and the client resends (the transfer still completes intact).
  const Outcome o = Download(/*paced=*/false, 0, kImageBytes);
  ASSERT_TRUE(o.finished);
  EXPECT_GT(o.lost, 0u);
  EXPECT_GT(o.resent, 0u);
  EXPECT_TRUE(o.staged_intact);
  std::printf("unpaced: %u frames lost, %u resent, %.3f s (%.1f kB/s)\n", o.lost, o.resent,
              o.seconds, kImageBytes / o.seconds / 1000);
}

}  // namespace
}  // namespace volcomp
