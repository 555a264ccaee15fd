// The board's settings: its installation (BoardConfig) plus the CAN node's settings, as a store
// (0x1010) saves them and a start applies them. One definition for the firmware, the Linux board
// and the PC tool; the objects and file keys bound to the fields are the VOLCOMP_OD_SETTING rows
// of lib/canopen od_entries.def.
//
// ValidateSettings() names the first broken rule (ConfigRule); the stored record
// (SerializeSettings/DeserializeSettings) is kSettingsBytes, little-endian and versioned, and a
// record is only taken when it validates. Freestanding: no heap, callable from any context.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp {

/// What a board without stored settings uses for its CANopen node.
inline constexpr uint8_t kDefaultNodeId = 0x10;        // 0x2000:1
inline constexpr uint16_t kDefaultBitrateKbit = 1000;  // 0x2000:2
inline constexpr uint16_t kDefaultHeartbeatMs = 1000;  // 0x1017 (0 = off)
/// 0x1015 EMCY inhibit time, 100 us units: 10 ms. EMCY (COB-ID 0x080 + id) wins arbitration over
/// every PDO and SDO, so a burst of events (a chattering alarm input, a client hammering a locked
/// object: one EMCY pair each) would otherwise delay the controller's setpoints; 10 ms bounds EMCY
/// to 100 frames/s while the first EMCY after a quiet spell still leaves at once.
inline constexpr uint16_t kDefaultEmcyInhibit100us = 100;

/// A PDO's CiA 301 parameters as stored (0x1800+n / 0x1A00+n for a TPDO). `cob_id` in stored
/// form: an 11-bit CAN-ID equal to the pre-defined base (0x180, 0x280, 0x200 ...: node-ID 0, which
/// no node has) means "base + the node-ID in force", so a stored default follows a node-ID change
/// (CiA 301 pre-defined connection set); any other value is the CAN-ID itself.
inline constexpr uint8_t kPdoMaxMapped = 8;
struct PdoSettings {
  uint32_t cob_id = 0x80000000u;         // :1, bit 31 set: the PDO does not exist
  uint8_t transmission_type = 254;       // :2 (254/255: event-driven)
  uint16_t inhibit_100us = 0;            // :3 (0 = none)
  uint16_t event_timer_ms = 0;           // :5 (0 = off)
  uint8_t mapped = 0;                    // 0x1A00+n:0
  uint32_t mapping[kPdoMaxMapped] = {};  // index << 16 | sub << 8 | length in bits
};

/// The board's transmit PDOs (docs/canopen.md, "PDOs"): their defaults.
inline constexpr uint8_t kTpdoCount = 2;
inline constexpr uint16_t kDefaultTpdoInhibit100us = 200;  // 20 ms
inline constexpr uint16_t kDefaultTpdoEventTimerMs = 100;
/// TPDO1 (COB-ID 0x180 + node-ID): device state 0x2122 (U16), clamped axes 0x2125 (U8), rate-
/// limited axes 0x2126 (U8), applied correction steps 0x2138:1-2 (I16 each). TPDO2 (0x280 +
/// node-ID): 0x2138:3-6.
constexpr PdoSettings DefaultTpdo(uint8_t n) {
  PdoSettings p;
  p.transmission_type = 254;
  p.inhibit_100us = kDefaultTpdoInhibit100us;
  p.event_timer_ms = kDefaultTpdoEventTimerMs;
  constexpr uint32_t kCorrection = 0x2138u << 16 | 16u;  // 0x2138:sub, I16
  if (n == 0) {
    p.cob_id = 0x180;  // + node-ID (stored form)
    p.mapped = 5;
    p.mapping[0] = 0x2122u << 16 | 16u;  // device state, U16
    p.mapping[1] = 0x2125u << 16 | 8u;   // clamped axes, U8
    p.mapping[2] = 0x2126u << 16 | 8u;   // rate-limited axes, U8
    p.mapping[3] = kCorrection | 1u << 8;
    p.mapping[4] = kCorrection | 2u << 8;
  } else {
    p.cob_id = 0x280;
    p.mapped = 4;
    for (uint32_t a = 0; a < 4; ++a) p.mapping[a] = kCorrection | (3u + a) << 8;
  }
  return p;
}

/// The board's receive PDOs (docs/canopen.md, "PDOs"), event-driven (acted on at receipt), their
/// mappings static (0x1600+n read-only): only the COB-ID and the transmission type are stored.
/// RPDO1 (COB-ID 0x200 + node-ID, stored form): the command word 0x2127 (U16). RPDO2 (0x300 +
/// node-ID) and RPDO3 (0x400 + node-ID): the temperatures 0x2150:1-4 and 0x2150:5-8 (I16 each, a
/// frame of 8 bytes); a channel the frame should not feed carries 0x8000.
inline constexpr uint8_t kRpdoCount = 3;
inline constexpr uint8_t kRpdoTemperatureChannels = 4;  // per RPDO2 / RPDO3 frame
constexpr PdoSettings DefaultRpdo(uint8_t n) {
  PdoSettings p;
  p.cob_id = 0x200u + 0x100u * n;  // + node-ID (stored form)
  p.transmission_type = 254;
  if (n == 0) {
    p.mapped = 1;
    p.mapping[0] = 0x2127u << 16 | 16u;  // command word, U16
  } else {
    p.mapped = kRpdoTemperatureChannels;
    for (uint32_t k = 0; k < kRpdoTemperatureChannels; ++k) {
      p.mapping[k] = 0x2150u << 16 | (1u + (n - 1u) * kRpdoTemperatureChannels + k) << 8 | 16u;
    }
  }
  return p;
}

struct BoardSettings {
  BoardConfig board = DefaultBoardConfig();
  uint8_t node_id = kDefaultNodeId;                                 // 1..127
  uint16_t bitrate_kbit = kDefaultBitrateKbit;                      // 10..1000
  uint16_t heartbeat_ms = kDefaultHeartbeatMs;                      // 0x1017, 0 = off
  uint16_t emcy_inhibit_100us = kDefaultEmcyInhibit100us;           // 0x1015, 0 = no inhibit
  PdoSettings tpdo[kTpdoCount] = {DefaultTpdo(0), DefaultTpdo(1)};  // 0x1800+n, 0x1A00+n
  PdoSettings rpdo[kRpdoCount] = {DefaultRpdo(0), DefaultRpdo(1),
                                  DefaultRpdo(2)};  // 0x1400+n (:1, :2) / 0x1600+n
  /// The temperature channels' sources and supervision limits (docs/thermal.md): every channel
  /// unused by default. The thermal model that uses them comes with the table image.
  thermal::ChannelConfig temperature[thermal::kMaxChannels] = {};
};

/// What drives the board's axes, for the rules that concern one kind of output stage only.
enum class OutputStage : uint8_t {
  kAny,          // the rules every board keeps (a stored record, a file before the board is known)
  kStepPulses,   // the step/dir board: also the step output's (ValidateStepOutputConfig)
  kCanSetpoints  // the CAN gateway: the rules every board keeps
};

/// Range checks of everything in `s` (the node settings, then ValidateBoardConfig, or
/// ValidateStepOutputConfig for kStepPulses, then the temperature channels); kConfigInvalid with
/// the first broken rule and its axis (or channel) in *finding (optional; kNone when ok).
Status ValidateSettings(const BoardSettings& s,
                        ConfigFinding* finding = nullptr,
                        OutputStage stage = OutputStage::kAny);

/// Serialized size of a BoardSettings record.
/// (Records of version 4 and older are kSettingsBytesV4 long: no PDO parameters; version 5,
/// kSettingsBytesV5: the TPDOs, no RPDO; version 6, kSettingsBytesV6: no temperature channels;
/// version 7, kSettingsBytesV7: RPDO1 only.)
inline constexpr uint32_t kPdoRecordBytes = 44;
inline constexpr uint32_t kRpdoRecordBytes = 8;
inline constexpr uint32_t kChannelRecordBytes = 12;
inline constexpr uint32_t kSettingsBytesV4 = 24 + table::kMaxAxes * 64 + 8;
inline constexpr uint32_t kSettingsBytesV5 = kSettingsBytesV4 + kTpdoCount * kPdoRecordBytes;
inline constexpr uint32_t kSettingsBytesV6 = kSettingsBytesV5 + kRpdoRecordBytes;
inline constexpr uint32_t kSettingsBytesV7 =
    kSettingsBytesV6 + thermal::kMaxChannels * kChannelRecordBytes;
inline constexpr uint32_t kSettingsBytes = kSettingsBytesV7 + (kRpdoCount - 1) * kRpdoRecordBytes;

/// Writes `s` into out[0, kSettingsBytes) (little-endian, versioned).
void SerializeSettings(const BoardSettings& s, uint8_t* out);
/// Reads and validates a record; kConfigInvalid for a record of another version or out of range.
/// A version-1 record (before 0x1015 was stored) gives the default EMCY inhibit time; a record of
/// version 4 or older (kSettingsBytesV4 long, before the PDOs) gives the default PDOs, one of
/// version 5 (kSettingsBytesV5, before the RPDO) the default RPDOs, one of version 6
/// (kSettingsBytesV6, before the temperature channels) every channel unused, one of version 7
/// (kSettingsBytesV7, before RPDO2 and RPDO3) their defaults.
Status DeserializeSettings(const uint8_t* in, uint32_t size, BoardSettings* s);

}  // namespace volcomp
