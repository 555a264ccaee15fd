// The owner's rules for what the bus may change.
#include "volcomp/firmware/board_policy.hpp"

#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp::firmware {

using canopen::SdoAbort;

void BoardPolicy::Restart() {
  unlocked_ = false;
  unlocked_at_ms_ = 0;
  now_ms_ = 0;
  has_active_ = false;
}

bool BoardPolicy::writable() const {
  const bool unlocked = unlocked_ && static_cast<uint32_t>(now_ms_ - unlocked_at_ms_) < kUnlockMs;
  return write_enable_input_ || unlocked;
}

SdoAbort BoardPolicy::WriteUnlock(uint32_t value) {
  if (value == canopen::kUnlockSignature) {
    unlocked_ = true;
    unlocked_at_ms_ = now_ms_;
    return SdoAbort::kNone;
  }
  unlocked_ = false;  // any other value locks
  return value == 0 ? SdoAbort::kNone : SdoAbort::kInvalidValue;
}

bool BoardPolicy::moving() const {
  const uint64_t still_ticks = uint64_t{kStillMs} * owner_.settings->board.tick_hz / 1000u;
  return owner_.control_tick->idle_ticks() < still_ticks;
}

SdoAbort BoardPolicy::MayActivate() const {
  return owner_.control_tick->all_referenced() && !moving() ? SdoAbort::kNone
                                                            : SdoAbort::kDeviceState;
}

Status BoardPolicy::Activate(const table::TableView& view) {
  PreparedTable& slot = owner_.hand_over->BeginWrite();
  const Status s = slot.Prepare(view, owner_.settings->board);
  if (!s.ok()) {
    owner_.hand_over->Abandon();
    return s;
  }
  owner_.hand_over->Publish();
  owner_.thermal->SetModel(view);
  has_active_ = true;
  active_id_ = view.table_id;
  active_crc_ = view.crc32;
  return Status::Ok();
}

void BoardPolicy::Deactivate() {
  owner_.hand_over->PublishClear();
  owner_.thermal->ClearModel();
  has_active_ = false;
}

void BoardPolicy::RequestReference(uint8_t mask) {
  if (!fault_) owner_.reference_requests->fetch_or(mask, std::memory_order_release);
}

}  // namespace volcomp::firmware
