// The configuration objects over SDO.
#include "volcomp/canopen_client/board_settings_io.hpp"

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/hosted/settings_ini.hpp"

namespace volcomp::canopen_client {

using canopen::ObjectId;
using canopen::SettingObject;
using canopen::SettingObjects;
using hosted::ObjectAddress;

Expected<BoardSettings> ReadSettings(NodeObjects& node) {
  BoardSettings s;  // the factory settings
  for (const SettingObject& o : SettingObjects()) {
    const canopen::ObjectEntry& e = canopen::Entry(o.id);
    SdoExpected<uint32_t> read = node.Read(o.id);
    // Firmware from before the channels' objects (0x2158-0x215D): its channels are unused, as its
    // settings in force (0x2124) say.
    if (o.channel != canopen::kNoChannel && AbortOf(read) == canopen::SdoAbort::kNoObject) continue;
    VOLCOMP_TRY_ASSIGN(const uint32_t raw,
                       Explained(std::move(read), "reading " + ObjectAddress(e) + " " + e.name));
    o.set(s, canopen::EntryValue(e, raw));
  }
  return s;
}

Expected<bool> SettingsPending(NodeObjects& node) {
  VOLCOMP_TRY_ASSIGN(const uint32_t state, Explained(node.Read(ObjectId::kDeviceState),
                                                     "reading the device state (2122:0)"));
  return canopen::DecodeDeviceState(static_cast<uint16_t>(state)).settings_pending;
}

Expected<BoardSettings> ReadSettingsInForce(NodeObjects& node) {
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> record,
                     Explained(node.ReadDomain(ObjectId::kSettingsInForce),
                               "reading the settings in force (2124:0)"));
  BoardSettings s;
  const Status st = DeserializeSettings(record.data(), static_cast<uint32_t>(record.size()), &s);
  if (!st.ok()) {
    return Fail(Error::kInputInvalid,
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
  if (k->per_channel) {
    text += " [" + hosted::ChannelSectionName(static_cast<uint8_t>(e.sub - 1)) + "]";
  }
  return text + " " + hosted::FormatSettingValue(*k, d.from) + " -> " +
         hosted::FormatSettingValue(*k, d.to);
}

Outcome WriteObjects(NodeObjects& node, const std::vector<Difference>& changes, size_t* written) {
  *written = 0;
  if (changes.empty()) return Outcome::Ok();
  VOLCOMP_TRY(Explained(EnsureWritable(node), "unlocking the board for writes"));
  for (const Difference& d : changes) {
    const canopen::ObjectEntry& e = canopen::Entry(d.id);
    VOLCOMP_TRY(
        Explained(node.Write(d.id, static_cast<uint32_t>(d.to)),
                  "writing " + ObjectAddress(e) + " " + e.name + " = " + std::to_string(d.to)));
    ++*written;
  }
  return Outcome::Ok();
}

Outcome StoreSettings(NodeObjects& node) {
  VOLCOMP_TRY(Explained(EnsureWritable(node), "unlocking the board for writes"));
  return Explained(node.Write(ObjectId::kStoreAll, canopen::kSaveSignature),
                   "storing the settings (1010:1 = \"save\")");
}

}  // namespace volcomp::canopen_client
