// The board's stored settings (BoardSettings, lib/config board_settings.hpp) in their own
// power-loss-safe dual bank: saved by CiA 301 "store parameters" (0x1010), forgotten by "restore
// default parameters" (0x1011), loaded by BoardApp::Start() (so a change takes effect after a node
// reset, as CANopen expects). Main loop only.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/firmware/dual_bank_store.hpp"
#include "volcomp/hal/flash.hpp"

namespace volcomp::firmware {

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
