// Mock clock, slow I/O, flash and CAN port for tests and the simulator. Each records what the
// firmware did into an optional Timeline and lets the test drive the inputs.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/mock/timeline.hpp"
#include "volcomp/hal/slow_io.hpp"

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
class MockCan : public CanPort {
 public:
  MockCan(MockClock* clock, Timeline* timeline, size_t tx_capacity = 64)
      : clock_(clock), timeline_(timeline), tx_capacity_(tx_capacity) {}
  void Inject(const CanFrame& frame) { rx_.push_back(frame); }
  /// Frames sent since the last TakeSent().
  std::vector<CanFrame> TakeSent();
  size_t pending_tx() const { return tx_.size(); }

 private:
  Status DoSend(const CanFrame& frame) override;
  bool DoReceive(CanFrame* frame) override;

  MockClock* clock_;
  Timeline* timeline_;
  size_t tx_capacity_;
  std::deque<CanFrame> rx_;
  std::vector<CanFrame> tx_;
};

}  // namespace volcomp::hal::mock
