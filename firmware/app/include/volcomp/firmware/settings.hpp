// Persistent board settings: the BoardConfig plus the CAN node settings, stored by CiA 301
// "store parameters" (0x1010) in their own power-loss-safe dual bank, restored to defaults by
// 0x1011, applied at start-up (so a change takes effect after a node reset, as CANopen expects).
#pragma once

#include <cstdint>

#include "volcomp/config/board_config.hpp"
#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/firmware/dual_bank_store.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/base/status.hpp"

namespace volcomp::firmware {

struct BoardSettings {
  BoardConfig board = DefaultBoardConfig();
  uint8_t node_id = canopen::kDefaultNodeId;                        // 1..127
  uint16_t bitrate_kbit = canopen::kDefaultBitrateKbit;             // 10..1000
  uint16_t heartbeat_ms = canopen::kDefaultHeartbeatMs;             // 0x1017, 0 = off
  uint16_t emcy_inhibit_100us = canopen::kDefaultEmcyInhibit100us;  // 0x1015, 0 = no inhibit
};

/// Range checks of everything in `s` (ValidateBoardConfig plus the node settings); the first
/// broken rule and its axis in *finding (optional).
Status ValidateSettings(const BoardSettings& s, ConfigFinding* finding = nullptr);

/// Serialized size of a BoardSettings record.
inline constexpr uint32_t kSettingsBytes = 24 + table::kMaxAxes * 64 + 8;

/// Writes `s` into out[0, kSettingsBytes) (little-endian, versioned).
void SerializeSettings(const BoardSettings& s, uint8_t* out);
/// Reads and validates a record; kConfigInvalid for a record of another version or out of range.
/// A version-1 record (before 0x1015 was stored) gives the default EMCY inhibit time.
Status DeserializeSettings(const uint8_t* in, uint32_t size, BoardSettings* s);

class SettingsStore {
 public:
  /// `flash` offsets [0, 2 * bank_size) hold the two banks.
  Status Init(hal::Flash* flash, uint32_t bank_size);
  /// The stored settings, or `defaults` when none are stored or they are invalid.
  BoardSettings Load(const BoardSettings& defaults);
  /// Stores `s` (atomic). kConfigInvalid when `s` is out of range; kIoError on flash failure.
  Status Save(const BoardSettings& s);
  /// Forgets the stored settings (next Load gives the defaults).
  Status Reset();

 private:
  DualBankStore bank_;
  // Settings are saved whole, in one call: the buffer only needs to hold a program unit or two.
  alignas(8) uint8_t buffer_[2 * DualBankStore::kMaxProgramUnit] = {};
};

}  // namespace volcomp::firmware
