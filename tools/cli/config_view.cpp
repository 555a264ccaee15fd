// The configuration objects as the `config` commands show them.
#include "config_view.hpp"

#include "volcomp/hosted/settings_ini.hpp"

namespace volcomp::cli {

using canopen::ObjectId;
using hosted::SettingKey;

std::string AxisOf(const canopen::ObjectEntry& e, const BoardSettings& s) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr || e.id == ObjectId::kAxisCountConfig ||
      !(k->per_axis || k->form == hosted::SettingForm::kAxisNames)) {
    return "";
  }
  const uint32_t a = e.sub - 1u;
  return a < s.board.axis_count ? std::string(1, s.board.axis[a].name) : std::to_string(e.sub);
}

std::string KeyName(const canopen::ObjectEntry& e) {
  if (e.id == ObjectId::kAxisCountConfig) return "axes (count)";
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr) return e.name;
  return k->form == hosted::SettingForm::kAxisNames ? "axes (name)" : k->key;
}

std::string ValueText(const canopen::ObjectEntry& e, int64_t v) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  if (k == nullptr || e.id == ObjectId::kAxisCountConfig) return std::to_string(v);
  return hosted::FormatSettingValue(*k, v);
}

std::string UnitOf(const canopen::ObjectEntry& e) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  return k != nullptr && e.id != ObjectId::kAxisCountConfig ? k->unit : "";
}

const char* PendingNote() {
  return "settings pending: these values are edited or stored but not in force until NMT reset "
         "node (`volcomp nmt reset`; edits not stored are then lost)";
}

Expected<BoardConfiguration> ReadConfiguration(canopen_client::NodeObjects& node) {
  BoardConfiguration c;
  VOLCOMP_TRY_ASSIGN(c.settings, canopen_client::ReadSettings(node));
  VOLCOMP_TRY_ASSIGN(c.pending, canopen_client::SettingsPending(node));
  return c;
}

}  // namespace volcomp::cli
