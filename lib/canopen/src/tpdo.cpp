// CiA 301 transmit PDO: mapping check, sampling and timing.
#include "volcomp/canopen/tpdo.hpp"

namespace volcomp::canopen {

namespace {

// The inhibit time on the millisecond clock: rounded up, plus one for the clock's resolution
// (as the EMCY inhibit time, node.cpp).
uint32_t GapMs(uint16_t inhibit_100us) {
  return inhibit_100us == 0 ? 0u : (inhibit_100us + 9u) / 10u + 1u;
}

const ObjectEntry* MappedEntry(uint32_t m) {
  return FindEntry(static_cast<uint16_t>(m >> 16), static_cast<uint8_t>(m >> 8));
}

}  // namespace

SdoAbort CheckTpdoMapping(const TpdoParameters& p) {
  if (p.mapped > kPdoMaxMapped) return SdoAbort::kPdoLength;
  uint32_t bits = 0;
  for (uint8_t i = 0; i < p.mapped; ++i) {
    const ObjectEntry* e = MappedEntry(p.mapping[i]);
    if (e == nullptr || !e->pdo_mappable || FixedSize(e->type) == 0 ||
        (p.mapping[i] & 0xFFu) != 8 * FixedSize(e->type)) {
      return SdoAbort::kCannotMap;
    }
    bits += p.mapping[i] & 0xFFu;
  }
  return bits > 64 ? SdoAbort::kPdoLength : SdoAbort::kNone;
}

void Tpdo::Configure(const TpdoParameters& p) {
  p_ = p;
  for (uint8_t i = 0; i < kPdoMaxMapped; ++i) {
    entries_[i] = i < p_.mapped ? MappedEntry(p_.mapping[i]) : nullptr;
  }
  sent_once_ = false;
  last_dlc_ = 0;
}

bool Tpdo::Sample(ObjectValues& values, uint8_t data[8], uint8_t* dlc) const {
  uint8_t n = 0;
  for (uint8_t i = 0; i < p_.mapped && i < kPdoMaxMapped; ++i) {
    const ObjectEntry* e = entries_[i];
    if (e == nullptr) return false;
    const uint32_t size = FixedSize(e->type);
    if (size == 0 || n + size > 8) return false;
    uint32_t copied = 0, total = 0;
    if (Failed(values.Read(*e, 0, data + n, size, &copied, &total)) || copied != size) return false;
    n = static_cast<uint8_t>(n + size);
  }
  *dlc = n;
  return true;
}

bool Tpdo::Poll(ObjectValues& values, bool operational, uint32_t now_ms, CanFrame* out) {
  if (!operational || (p_.cob_id & kPdoCobIdInvalid) != 0 || p_.mapped == 0) {
    sent_once_ = false;  // entering operational or re-enabling sends the state at once
    return false;
  }
  const uint32_t since = now_ms - last_sent_ms_;
  if (sent_once_ && since < GapMs(p_.inhibit_100us)) return false;
  uint8_t data[8] = {};
  uint8_t dlc = 0;
  if (!Sample(values, data, &dlc)) return false;
  bool changed = !sent_once_ || dlc != last_dlc_;
  for (uint8_t i = 0; i < dlc && !changed; ++i) changed = data[i] != last_data_[i];
  const bool timer = p_.event_timer_ms != 0 && since >= p_.event_timer_ms;
  if (!changed && !timer) return false;
  out->id = p_.cob_id & 0x7FFu;
  out->extended = false;
  out->rtr = false;
  out->dlc = dlc;
  for (uint8_t i = 0; i < 8; ++i) out->data[i] = i < dlc ? data[i] : 0;
  for (uint8_t i = 0; i < 8; ++i) last_data_[i] = data[i];
  last_dlc_ = dlc;
  last_sent_ms_ = now_ms;
  sent_once_ = true;
  return true;
}

}  // namespace volcomp::canopen
