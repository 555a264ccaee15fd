// The configuration objects over SDO.
#include "volcomp/board_ini/board_settings_io.hpp"

#include "volcomp/board_ini/board_ini.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::board_ini {

using canopen::ObjectId;
using firmware::BoardSettings;

void Require(const canopen_client::SdoFailure& r, const std::string& what) {
  // No answer at all (or no link) is a communication failure; everything else the board said.
  if (r.code == Error::kCommunication) throw tools::CommunicationError(what + ": " + r.message);
  throw tools::InputError(canopen_client::Explain(r, what).message);
}

BoardSettings ReadSettings(canopen_client::NodeObjects& node) {
  BoardSettings s = FactorySettings();
  for (const SettingObject& o : SettingObjects()) {
    const canopen::ObjectEntry& e = canopen::Entry(o.id);
    const uint32_t raw = Require(node.Read(o.id), "reading " + ObjectAddress(e) + " " + e.name);
    o.set(s, FromRaw(e, raw));
  }
  return s;
}

bool SettingsPending(canopen_client::NodeObjects& node) {
  const uint32_t state =
      Require(node.Read(ObjectId::kDeviceState), "reading the device state (2122:0)");
  return canopen::DecodeDeviceState(static_cast<uint16_t>(state)).settings_pending;
}

BoardSettings ReadSettingsInForce(canopen_client::NodeObjects& node) {
  const std::vector<uint8_t> record = Require(node.ReadDomain(ObjectId::kSettingsInForce),
                                              "reading the settings in force (2124:0)");
  BoardSettings s;
  const Status st =
      firmware::DeserializeSettings(record.data(), static_cast<uint32_t>(record.size()), &s);
  if (!st.ok()) {
    throw tools::InputError(
        "the settings in force (2124:0, " + std::to_string(record.size()) +
        " bytes) are not a settings record this tool reads: " + ErrorText(st.error()));
  }
  return s;
}

std::vector<Difference> Differences(const BoardSettings& a, const BoardSettings& b) {
  std::vector<Difference> out;
  for (const SettingObject& o : SettingObjects()) {
    if (o.get(a) != o.get(b)) out.push_back({o.id, o.get(a), o.get(b)});
  }
  return out;
}

std::string DescribeDifference(const Difference& d, const BoardSettings& names) {
  const canopen::ObjectEntry& e = canopen::Entry(d.id);
  const IniKey* k = KeyOf(d.id);
  if (k == nullptr || d.id == ObjectId::kAxisCountConfig) {
    return ObjectAddress(e) + " " + e.name + " " + std::to_string(d.from) + " -> " +
           std::to_string(d.to);
  }
  std::string text = ObjectAddress(e) + " " + k->key;
  if (k->per_axis || k->form == ValueForm::kAxisNames) {
    const uint8_t axis = static_cast<uint8_t>(e.sub - 1);
    text += axis < names.board.axis_count
                ? std::string(" (axis ") + names.board.axis[axis].name + ")"
                : " (axis " + std::to_string(e.sub) + ", not used)";
  }
  return text + " " + FormatValue(*k, d.from) + " -> " + FormatValue(*k, d.to);
}

void WriteObjects(canopen_client::NodeObjects& node,
                  const std::vector<Difference>& changes,
                  size_t* written) {
  *written = 0;
  if (changes.empty()) return;
  Require(canopen_client::EnsureWritable(node), "unlocking the board for writes");
  for (const Difference& d : changes) {
    const canopen::ObjectEntry& e = canopen::Entry(d.id);
    Require(node.Write(d.id, static_cast<uint32_t>(d.to)),
            "writing " + ObjectAddress(e) + " " + e.name + " = " + std::to_string(d.to));
    ++*written;
  }
}

void StoreSettings(canopen_client::NodeObjects& node) {
  Require(canopen_client::EnsureWritable(node), "unlocking the board for writes");
  Require(node.Write(ObjectId::kStoreAll, canopen::kSaveSignature),
          "storing the settings (1010:1 = \"save\")");
}

}  // namespace volcomp::board_ini
