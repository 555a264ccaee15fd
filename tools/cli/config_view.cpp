// The configuration objects as the `config` commands show them.
#include "config_view.hpp"

#include <cstdio>

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

uint8_t ChannelOf(const canopen::ObjectEntry& e) {
  const SettingKey* k = hosted::SettingKeyOf(e.id);
  return k != nullptr && k->per_channel ? e.sub : 0;
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

JsonValue SwitchAccelBounds(const BoardSettings& s) {
  JsonValue list = JsonValue::Array();
  const uint32_t divider = CompensationDivider(s.board.tick_hz);
  for (uint8_t i = 0; i < s.board.axis_count; ++i) {
    const AxisConfig& a = s.board.axis[i];
    const SwitchAccelInEffect e = DirectionSwitchAccelInEffect(a, s.board.tick_hz, divider);
    if (e.bound == SwitchAccelBound::kNone) continue;
    const auto id =
        static_cast<ObjectId>(static_cast<uint16_t>(ObjectId::kAxisDirectionSwitchAccel1) + i);
    JsonValue x = JsonValue::Object();
    x.Set("object", hosted::ObjectAddress(canopen::Entry(id)));
    x.Set("axis", std::string(1, a.name));
    x.Set("configured", uint64_t{a.direction_switch_accel_steps_s2});
    x.Set("in_effect", uint64_t{e.steps_s2});
    x.Set("compensation_hz", uint64_t{s.board.tick_hz / divider});
    x.Set("bound", e.bound == SwitchAccelBound::kPeriod ? "compensation period" : "drive rate");
    list.Push(std::move(x));
  }
  return list;
}

std::string SwitchAccelBoundText(const JsonValue& x) {
  const bool period = x.get("bound")->string == "compensation period";
  char line[320];
  std::snprintf(line, sizeof line,
                "axis %s: direction_switch_accel (%s) %lld steps/s2 takes effect as %lld steps/s2: "
                "%s",
                x.get("axis")->string.c_str(), x.get("object")->string.c_str(),
                static_cast<long long>(x.get("configured")->integer),
                static_cast<long long>(x.get("in_effect")->integer),
                period
                    ? "the most one step per compensation period represents at "
                    : "it reaches the rate the drive has beyond the input within one period at ");
  return std::string(line) + std::to_string(x.get("compensation_hz")->integer) + " Hz";
}

}  // namespace volcomp::cli
