// Mock clock, slow I/O, flash, CAN port and tick timer for tests and the simulator. Each records
// what the firmware did into an optional Timeline (or its own counters) and lets the test drive
// the inputs.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/mock/timeline.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/tick_timer.hpp"

namespace volcomp::hal::mock {

/// A clock the test advances by hand.
class MockClock : public Clock {
 public:
  void Set(uint64_t t_ns) { now_ = t_ns; }
  void Advance(uint64_t dt_ns) { now_ += dt_ns; }
  uint64_t now() const { return now_; }

 private:
  uint64_t DoNowNs() override { return now_; }
  uint64_t now_ = 0;
};

class MockSlowIo : public SlowIo {
 public:
  MockSlowIo(MockClock* clock, Timeline* timeline) : clock_(clock), timeline_(timeline) {}
  void SetInput(InputLine line, bool level) { in_[static_cast<int>(line)] = level; }
  bool output(OutputLine line) const { return out_[static_cast<int>(line)]; }

 private:
  bool DoRead(InputLine line) override { return in_[static_cast<int>(line)]; }
  void DoWrite(OutputLine line, bool level) override;

  MockClock* clock_;
  Timeline* timeline_;
  bool in_[static_cast<int>(InputLine::kCount)] = {};
  bool out_[static_cast<int>(OutputLine::kCount)] = {};
};

/// NOR-flash model: erase to 0xFF by sector, program clears bits only (programming a 0 to 1 is
/// an error, as on real flash), with an optional injected power loss: after `n` more successful
/// program/erase operations the next one writes only part of its data and fails, and every later
/// operation fails until PowerCycle().
class MockFlash : public Flash {
 public:
  MockFlash(uint32_t size,
            uint32_t sector_size,
            uint32_t program_unit,
            MockClock* clock,
            Timeline* timeline);

  /// Arms a power loss after `ops` further operations (0 = the very next one).
  void InjectPowerLossAfter(uint32_t ops) { power_loss_in_ = static_cast<int64_t>(ops); }
  /// Restores power (the content stays as it was when power was lost).
  void PowerCycle() {
    powered_ = true;
    power_loss_in_ = -1;
  }
  bool powered() const { return powered_; }
  uint32_t erase_count() const { return erases_; }
  uint32_t program_count() const { return programs_; }
  std::vector<uint8_t>& raw() { return storage_; }

 private:
  uint32_t DoSize() const override { return size_; }
  uint32_t DoSectorSize() const override { return sector_; }
  uint32_t DoProgramUnit() const override { return unit_; }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override;
  const uint8_t* DoMap(uint32_t offset) const override;
  enum class Power { kOn, kLostNow, kOff };
  Power CheckPower();

  uint32_t size_, sector_, unit_;
  MockClock* clock_;
  Timeline* timeline_;
  std::vector<uint8_t> storage_;  // 4-byte aligned (vector of bytes from operator new)
  int64_t power_loss_in_ = -1;
  bool powered_ = true;
  uint32_t erases_ = 0;
  uint32_t programs_ = 0;
};

/// A CAN port whose transmitted frames are recorded and whose received frames the test injects.
/// SetBitrate() records the rate (every rate is accepted unless the test makes it refuse).
class MockCan : public CanPort {
 public:
  MockCan(MockClock* clock, Timeline* timeline, size_t tx_capacity = 64)
      : clock_(clock), timeline_(timeline), tx_capacity_(tx_capacity) {}
  void Inject(const CanFrame& frame) { rx_.push_back(frame); }
  /// Frames sent since the last TakeSent().
  std::vector<CanFrame> TakeSent();
  size_t pending_tx() const { return tx_.size(); }
  /// The bit rate last applied (0 = never), and how many times one was applied.
  uint32_t bitrate_bps() const { return bitrate_bps_; }
  uint32_t bitrate_changes() const { return bitrate_changes_; }
  /// Makes the next SetBitrate() calls fail with `status` (Ok: accept again).
  void RefuseBitrate(Status status) { refuse_ = status; }

 private:
  Status DoSend(const CanFrame& frame) override;
  bool DoReceive(CanFrame* frame) override;
  Status DoSetBitrate(uint32_t bitrate_bps) override;

  MockClock* clock_;
  Timeline* timeline_;
  size_t tx_capacity_;
  std::deque<CanFrame> rx_;
  std::vector<CanFrame> tx_;
  uint32_t bitrate_bps_ = 0;
  uint32_t bitrate_changes_ = 0;
  Status refuse_;
};

/// A tick timer that only records: the test (or the simulated board, which ticks the firmware at
/// rate_hz() while running()) plays the hardware. Any rate is accepted unless the test makes it
/// refuse; starts() counts Start() calls so a caller sees a restart.
class MockTickTimer : public TickTimer {
 public:
  bool running() const { return running_; }
  uint32_t starts() const { return starts_; }
  uint32_t stops() const { return stops_; }
  /// Makes SetRate() refuse rates above `max_hz` with kConfigInvalid (0 = accept every rate).
  void RefuseAbove(uint32_t max_hz) { refuse_above_hz_ = max_hz; }

 private:
  Status DoSetRate(uint32_t tick_hz) override;
  Status DoStart() override;
  void DoStop() override;
  uint32_t DoRateHz() const override { return rate_hz_; }

  uint32_t rate_hz_ = 0;
  uint32_t refuse_above_hz_ = 0;
  bool running_ = false;
  uint32_t starts_ = 0;
  uint32_t stops_ = 0;
};

}  // namespace volcomp::hal::mock
