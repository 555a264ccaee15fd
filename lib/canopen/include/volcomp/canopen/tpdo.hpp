// CiA 301 transmit PDO (one channel): its communication parameters (0x1800+n) and mapping
// (0x1A00+n), the mapped values sampled through ObjectValues, and when a frame is due:
// transmission types 254/255 (event-driven, the only ones a node without SYNC offers), sent on a
// change of the mapped bytes once the inhibit time has passed, and on the event timer; only in
// NMT operational. Single-threaded (main loop); no heap. The node (node.hpp) owns the board's
// TPDOs and serves their objects: docs/canopen.md, "PDOs".
#pragma once

#include <cstdint>

#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/config/board_settings.hpp"

namespace volcomp::canopen {

using ::volcomp::kPdoMaxMapped;
inline constexpr uint32_t kPdoCobIdInvalid = 0x80000000u;  // bit 31: the PDO does not exist
inline constexpr uint32_t kPdoCobIdNoRtr = 0x40000000u;    // bit 30: no RTR allowed
inline constexpr uint8_t kPdoEventDrivenManufacturer = 254;
inline constexpr uint8_t kPdoEventDrivenProfile = 255;

/// A mapping entry (0x1A00+n:1..8): index << 16 | sub << 8 | length in bits.
constexpr uint32_t PdoMapping(uint16_t index, uint8_t sub, uint8_t bits) {
  return uint32_t{index} << 16 | uint32_t{sub} << 8 | bits;
}

/// The parameters (lib/config board_settings.hpp, where the board stores them): cob_id :1 (bits
/// 10..0 the CAN-ID, bit 31 kPdoCobIdInvalid), transmission_type :2, inhibit_100us :3 (0 =
/// none), event_timer_ms :5 (0 = off), mapped (0x1A00+n:0) and mapping[] (0x1A00+n:1..8). A
/// default-constructed one does not exist (bit 31 set, nothing mapped).
using TpdoParameters = ::volcomp::PdoSettings;

/// kNone when every mapping entry names a mappable (sub-)entry of the dictionary
/// (ObjectEntry::pdo_mappable: a produced ro numeric value) with its size in bits and the entries
/// fit 8 bytes; else the CiA 301 abort a write making it so gets (0x06040041 cannot be mapped,
/// 0x06040042 exceeds the PDO length).
SdoAbort CheckTpdoMapping(const TpdoParameters& p);

class Tpdo {
 public:
  /// New parameters in force (the timers restart: the next due frame is sent at once).
  void Configure(const TpdoParameters& p);
  const TpdoParameters& parameters() const { return p_; }
  /// The next due frame is sent at once (entering NMT operational: the caller need not Poll()
  /// outside operational).
  void Restart() { sent_once_ = false; }
  /// The frame due at `now_ms`, if any: the PDO valid, `operational`, and either the mapped bytes
  /// changed since the last frame sent or the event timer elapsed, never sooner than the inhibit
  /// time after the last one. The values are read through `values`; a read that fails sends
  /// nothing.
  bool Poll(ObjectValues& values, bool operational, uint32_t now_ms, CanFrame* out);

 private:
  bool Sample(ObjectValues& values, uint8_t data[8], uint8_t* dlc) const;

  TpdoParameters p_;
  const ObjectEntry* entries_[kPdoMaxMapped] = {};  // of p_.mapping, found once by Configure()
  bool sent_once_ = false;
  uint32_t last_sent_ms_ = 0;
  uint8_t last_data_[8] = {};
  uint8_t last_dlc_ = 0;
};

}  // namespace volcomp::canopen
