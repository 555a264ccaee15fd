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

struct BoardSettings {
  BoardConfig board = DefaultBoardConfig();
  uint8_t node_id = kDefaultNodeId;                        // 1..127
  uint16_t bitrate_kbit = kDefaultBitrateKbit;             // 10..1000
  uint16_t heartbeat_ms = kDefaultHeartbeatMs;             // 0x1017, 0 = off
  uint16_t emcy_inhibit_100us = kDefaultEmcyInhibit100us;  // 0x1015, 0 = no inhibit
};

/// What drives the board's axes, for the rules that concern one kind of output stage only.
enum class OutputStage : uint8_t {
  kAny,          // the rules every board keeps (a stored record, a file before the board is known)
  kStepPulses,   // the step/dir board: also the step output's (ValidateStepOutputConfig)
  kCanSetpoints  // the CAN gateway: the rules every board keeps
};

/// Range checks of everything in `s` (the node settings, then ValidateBoardConfig, or
/// ValidateStepOutputConfig for kStepPulses); kConfigInvalid with the first broken rule and its
/// axis in *finding (optional; kNone when ok).
Status ValidateSettings(const BoardSettings& s,
                        ConfigFinding* finding = nullptr,
                        OutputStage stage = OutputStage::kAny);

/// Serialized size of a BoardSettings record.
inline constexpr uint32_t kSettingsBytes = 24 + table::kMaxAxes * 64 + 8;

/// Writes `s` into out[0, kSettingsBytes) (little-endian, versioned).
void SerializeSettings(const BoardSettings& s, uint8_t* out);
/// Reads and validates a record; kConfigInvalid for a record of another version or out of range.
/// A version-1 record (before 0x1015 was stored) gives the default EMCY inhibit time.
Status DeserializeSettings(const uint8_t* in, uint32_t size, BoardSettings* s);

}  // namespace volcomp
