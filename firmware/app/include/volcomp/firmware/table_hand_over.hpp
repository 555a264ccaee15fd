// Hands prepared tables from the main loop to the control tick without copying them in the tick.
//
// Two PreparedTable slots. The main loop prepares a table in the slot the tick does not use and
// publishes it; the tick, at its next run, points the compensator at that slot (no copy) and
// records it as the slot in use. The table the tick uses is therefore never written.
//
// Protocol (request_ is the only word both sides write):
//   main loop  BeginWrite(): request_ = none (withdraws a request the tick has not taken yet);
//              reads in_use_ (stable from now on: the tick changes it only when it takes a
//              request) and returns the other slot;
//              fills the slot (PreparedTable::Prepare), then Publish(): request_ = that slot
//              (release), or Abandon(): request_ = what BeginWrite() withdrew;
//              PublishClear(): request_ = clear (the tick drops its table).
//   tick       Take(): request_ (acquire); when set, in_use_ = the slot (or none), request_ = none.
// The tick must run to completion without the main loop running in between (on the MCU it is an
// interrupt that preempts the main loop, never the reverse; on the host both run in one thread);
// the main loop must not be re-entered.
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/control/compensator.hpp"

namespace volcomp::firmware {

class TableHandOver {
 public:
  // ---- Main loop -------------------------------------------------------------------------

  /// The slot to prepare the next table in (never the one the tick uses).
  PreparedTable& BeginWrite() {
    withdrawn_ = request_.exchange(kNone, std::memory_order_acq_rel);
    free_ = in_use_.load(std::memory_order_acquire) == 0 ? 1 : 0;
    return slots_[free_];
  }
  /// Hands the slot of the last BeginWrite() to the tick.
  void Publish() {
    request_.store(static_cast<uint8_t>(kSlot0 + free_), std::memory_order_release);
  }
  /// Leaves the hand-over as it was before BeginWrite() (the slot was not changed, or is not to
  /// be used).
  void Abandon() { request_.store(withdrawn_, std::memory_order_release); }
  /// Tells the tick to drop its table.
  void PublishClear() { request_.store(kClear, std::memory_order_release); }

  // ---- Tick --------------------------------------------------------------------------------

  /// True when the main loop handed something over since the last call: `*table` is then the table
  /// to use from now on, or null to drop the table. One load when nothing was handed over.
  bool Take(const PreparedTable** table) {
    const uint8_t r = request_.load(std::memory_order_acquire);
    if (r == kNone) return false;
    const uint8_t slot = r == kClear ? kNoSlot : static_cast<uint8_t>(r - kSlot0);
    *table = slot == kNoSlot ? nullptr : &slots_[slot];
    in_use_.store(slot, std::memory_order_release);
    request_.store(kNone, std::memory_order_release);
    return true;
  }

 private:
  static constexpr uint8_t kNone = 0, kSlot0 = 1, kClear = 3;  // request_ values (kSlot0 + slot)
  static constexpr uint8_t kNoSlot = 2;                        // in_use_: no table

  PreparedTable slots_[2];
  std::atomic<uint8_t> request_{kNone};
  std::atomic<uint8_t> in_use_{kNoSlot};  // written by the tick only
  uint8_t free_ = 0;                      // main loop only
  uint8_t withdrawn_ = kNone;             // main loop only
};

}  // namespace volcomp::firmware
