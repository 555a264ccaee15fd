// Mock slow I/O, flash, CAN and tick timer.
#include "volcomp/hal/mock/mock_devices.hpp"

#include <cstring>

namespace volcomp::hal::mock {

void MockSlowIo::DoWrite(OutputLine line, bool level) {
  bool& out = out_[static_cast<int>(line)];
  if (out != level && timeline_ != nullptr) {
    timeline_->Record(
        {clock_->now(), EventKind::kOutputLine, static_cast<uint8_t>(line), level ? 1 : 0});
  }
  out = level;
}

MockFlash::MockFlash(uint32_t size,
                     uint32_t sector_size,
                     uint32_t program_unit,
                     MockClock* clock,
                     Timeline* timeline)
    : size_(size),
      sector_(sector_size),
      unit_(program_unit),
      clock_(clock),
      timeline_(timeline),
      storage_(size, 0xFF) {}

MockFlash::Power MockFlash::CheckPower() {
  if (!powered_) return Power::kOff;
  if (power_loss_in_ == 0) {
    powered_ = false;
    return Power::kLostNow;
  }
  if (power_loss_in_ > 0) --power_loss_in_;
  return Power::kOn;
}

Status MockFlash::DoErase(uint32_t offset) {
  const Power power = CheckPower();
  if (power == Power::kLostNow) std::memset(storage_.data() + offset, 0xFF, sector_ / 2);
  if (power != Power::kOn) return Error::kIoError;  // interrupted erase: sector half erased
  std::memset(storage_.data() + offset, 0xFF, sector_);
  ++erases_;
  if (timeline_ != nullptr) timeline_->Record({clock_->now(), EventKind::kFlashErase, 0, offset});
  return Status::Ok();
}

Status MockFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) {
  const Power power = CheckPower();
  if (power == Power::kOff) return Error::kIoError;
  const bool lost = power == Power::kLostNow;
  const uint32_t n = lost ? (bytes / 2) / unit_ * unit_ : bytes;  // interrupted: first half only
  for (uint32_t i = 0; i < n; ++i) {
    if ((storage_[offset + i] & data[i]) != data[i]) return Error::kIoError;  // 0 -> 1 refused
    storage_[offset + i] = data[i];
  }
  if (lost) return Error::kIoError;
  ++programs_;
  if (timeline_ != nullptr) {
    timeline_->Record({clock_->now(), EventKind::kFlashProgram, 0, offset});
  }
  return Status::Ok();
}

const uint8_t* MockFlash::DoMap(uint32_t offset) const { return storage_.data() + offset; }

std::vector<CanFrame> MockCan::TakeSent() {
  std::vector<CanFrame> out;
  out.swap(tx_);
  return out;
}

Status MockCan::DoSend(const CanFrame& frame) {
  if (tx_.size() >= tx_capacity_) return Error::kFull;
  tx_.push_back(frame);
  if (timeline_ != nullptr) timeline_->Record({clock_->now(), EventKind::kCanTx, 0, frame.id});
  return Status::Ok();
}

bool MockCan::DoReceive(CanFrame* frame) {
  if (rx_.empty()) return false;
  *frame = rx_.front();
  rx_.pop_front();
  return true;
}

Status MockCan::DoSetBitrate(uint32_t bitrate_bps) {
  if (!refuse_.ok()) return refuse_;
  bitrate_bps_ = bitrate_bps;
  ++bitrate_changes_;
  return Status::Ok();
}

Status MockTickTimer::DoSetRate(uint32_t tick_hz) {
  if (running_) return Error::kBusy;
  if (refuse_above_hz_ != 0 && tick_hz > refuse_above_hz_) return Error::kConfigInvalid;
  rate_hz_ = tick_hz;
  return Status::Ok();
}

Status MockTickTimer::DoStart() {
  if (rate_hz_ == 0) return Error::kNotReady;
  running_ = true;
  ++starts_;
  return Status::Ok();
}

void MockTickTimer::DoStop() {
  if (running_) ++stops_;
  running_ = false;
}

}  // namespace volcomp::hal::mock
