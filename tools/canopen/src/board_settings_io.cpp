// The configuration objects over SDO.
#include "volcomp/canopen_client/board_settings_io.hpp"

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::canopen_client {

using canopen::ObjectId;
using canopen::SettingObject;
using canopen::SettingObjects;
using hosted::ObjectAddress;

void Require(const SdoResult& r, const std::string& what) {
  if (r.ok) return;
  // No answer at all is a communication failure; everything else the board said.
  if (!r.aborted_by_server && r.abort_code == canopen::SdoAbort::kTimeout) {
    throw tools::CommunicationError(what + ": " + r.message);
  }
  throw tools::InputError(Explain(r, what).message);
}

BoardSettings ReadSettings(NodeObjects& node) {
  BoardSettings s;  // the factory settings
  for (const SettingObject& o : SettingObjects()) {
    const canopen::ObjectEntry& e = canopen::Entry(o.id);
    uint32_t raw = 0;
    Require(node.Read(o.id, &raw), "reading " + ObjectAddress(e) + " " + e.name);
    o.set(s, canopen::EntryValue(e, raw));
  }
  return s;
}

bool SettingsPending(NodeObjects& node) {
  uint32_t state = 0;
  Require(node.Read(ObjectId::kDeviceState, &state), "reading the device state (2122:0)");
  return canopen::DecodeDeviceState(static_cast<uint16_t>(state)).settings_pending;
}

BoardSettings ReadSettingsInForce(NodeObjects& node) {
  std::vector<uint8_t> record;
  Require(node.UploadDomain(ObjectId::kSettingsInForce, &record),
          "reading the settings in force (2124:0)");
  BoardSettings s;
  const Status st = DeserializeSettings(record.data(), static_cast<uint32_t>(record.size()), &s);
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
  const hosted::SettingKey* k = hosted::SettingKeyOf(d.id);
  if (k == nullptr || d.id == ObjectId::kAxisCountConfig) {
    return ObjectAddress(e) + " " + e.name + " " + std::to_string(d.from) + " -> " +
           std::to_string(d.to);
  }
  std::string text = ObjectAddress(e) + " " + k->key;
  if (k->per_axis || k->form == hosted::SettingForm::kAxisNames) {
    const uint8_t axis = static_cast<uint8_t>(e.sub - 1);
    text += axis < names.board.axis_count
                ? std::string(" (axis ") + names.board.axis[axis].name + ")"
                : " (axis " + std::to_string(e.sub) + ", not used)";
  }
  return text + " " + hosted::FormatSettingValue(*k, d.from) + " -> " +
         hosted::FormatSettingValue(*k, d.to);
}

void WriteObjects(NodeObjects& node, const std::vector<Difference>& changes, size_t* written) {
  *written = 0;
  if (changes.empty()) return;
  Require(EnsureWritable(node), "unlocking the board for writes");
  for (const Difference& d : changes) {
    const canopen::ObjectEntry& e = canopen::Entry(d.id);
    Require(node.Write(d.id, static_cast<uint32_t>(d.to)),
            "writing " + ObjectAddress(e) + " " + e.name + " = " + std::to_string(d.to));
    ++*written;
  }
}

void StoreSettings(NodeObjects& node) {
  Require(EnsureWritable(node), "unlocking the board for writes");
  Require(node.Write(ObjectId::kStoreAll, canopen::kSaveSignature),
          "storing the settings (1010:1 = \"save\")");
}

}  // namespace volcomp::canopen_client
