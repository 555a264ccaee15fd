// The stored settings in their dual bank.
#include "volcomp/firmware/settings_store.hpp"

namespace volcomp::firmware {

Status SettingsStore::Init(hal::Flash* flash, uint32_t bank_size) {
  return bank_.Init(flash, bank_size, buffer_, sizeof buffer_);
}

BoardSettings SettingsStore::Load(const BoardSettings& defaults) {
  bank_.Mount();
  BoardSettings s;
  if (bank_.has_committed() &&
      DeserializeSettings(bank_.committed_data(), bank_.committed_size(), &s).ok()) {
    return s;
  }
  return defaults;
}

Status SettingsStore::Save(const BoardSettings& s) {
  VOLCOMP_TRY(ValidateSettings(s));
  uint8_t buf[kSettingsBytes];
  SerializeSettings(s, buf);
  VOLCOMP_TRY(bank_.BeginStaging());
  VOLCOMP_TRY(bank_.Append(buf, kSettingsBytes));
  VOLCOMP_TRY(bank_.FinishStaging());
  return bank_.Commit();
}

Status SettingsStore::Reset() { return bank_.Revoke(); }

}  // namespace volcomp::firmware
