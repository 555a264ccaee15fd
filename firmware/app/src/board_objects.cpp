// The board's object dictionary values.
#include "volcomp/firmware/board_objects.hpp"

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen/setting_objects.hpp"

namespace volcomp::firmware {
namespace {

using canopen::ObjectEntry;
using canopen::ObjectId;
using canopen::SdoAbort;

SdoAbort CopyOut(const uint8_t* src,
                 uint32_t src_size,
                 uint32_t offset,
                 uint8_t* buf,
                 uint32_t cap,
                 uint32_t* copied,
                 uint32_t* total) {
  *total = src_size;
  *copied = 0;
  while (offset + *copied < src_size && *copied < cap) {
    buf[*copied] = src[offset + *copied];
    ++*copied;
  }
  return SdoAbort::kNone;
}

uint32_t StringLength(const char* s) {
  uint32_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

using ValueRead = uint32_t (*)(const BoardObjects& o);

// Numbers of a fixed size as the object's raw value (signed ones in two's complement).
template <class T>
constexpr uint32_t Raw(T v) {
  return static_cast<uint32_t>(v);
}

// The produced values, one reader per dictionary entry (null for entries that are not
// VOLCOMP_OD_VALUE rows), expanded from od_entries.def: each calls the accessor its row names;
// per-axis values read 0 on the axes that are not configured.
// clang-format off
#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name) nullptr,
#define VOLCOMP_OD_VALUE(id, index, sub, type, access, def, source, name)                       \
  [](const BoardObjects& o) { return Raw(o.source()); },
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, key, name) nullptr,
#define VOLCOMP_OD_AXIS_VALUE(source, a)                                                        \
  [](const BoardObjects& o) { return a < o.axis_count() ? Raw(o.source(a)) : 0u; },
#define VOLCOMP_OD_AXIS_ARRAY(id, index, type, access, def, source, name)                       \
  nullptr, VOLCOMP_OD_AXIS_VALUE(source, 0) VOLCOMP_OD_AXIS_VALUE(source, 1)                   \
  VOLCOMP_OD_AXIS_VALUE(source, 2) VOLCOMP_OD_AXIS_VALUE(source, 3)                             \
  VOLCOMP_OD_AXIS_VALUE(source, 4) VOLCOMP_OD_AXIS_VALUE(source, 5)
#define VOLCOMP_OD_CHANNEL_VALUE(source, ch) [](const BoardObjects& o) { return Raw(o.source(ch)); },
#define VOLCOMP_OD_CHANNEL_COMMANDS(id, index, type, def, source, name)                         \
  VOLCOMP_OD_CHANNEL_ARRAY(id, index, type, kRw, def, source, name)
#define VOLCOMP_OD_CHANNEL_ARRAY(id, index, type, access, def, source, name)                    \
  nullptr, VOLCOMP_OD_CHANNEL_VALUE(source, 0) VOLCOMP_OD_CHANNEL_VALUE(source, 1)             \
  VOLCOMP_OD_CHANNEL_VALUE(source, 2) VOLCOMP_OD_CHANNEL_VALUE(source, 3)                       \
  VOLCOMP_OD_CHANNEL_VALUE(source, 4) VOLCOMP_OD_CHANNEL_VALUE(source, 5)                       \
  VOLCOMP_OD_CHANNEL_VALUE(source, 6) VOLCOMP_OD_CHANNEL_VALUE(source, 7)
constexpr ValueRead kValues[] = {
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
};
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_VALUE
#undef VOLCOMP_OD_SETTING
#undef VOLCOMP_OD_AXIS_VALUE
#undef VOLCOMP_OD_AXIS_ARRAY
#undef VOLCOMP_OD_CHANNEL_VALUE
#undef VOLCOMP_OD_CHANNEL_ARRAY
#undef VOLCOMP_OD_CHANNEL_COMMANDS
// clang-format on
static_assert(sizeof(kValues) / sizeof(kValues[0]) == static_cast<size_t>(ObjectId::kCount),
              "one value reader per ObjectId");

}  // namespace

BoardObjects::BoardObjects(const Parts& parts, const IdentityInfo& identity)
    : parts_(parts), identity_(identity) {}

void BoardObjects::ResetPendingSettings() {
  pending_ = *parts_.settings_in_force;
  settings_pending_ = false;
}

BoardSettings BoardObjects::WithCommunication(BoardSettings s) const {
  const canopen::CommunicationParameters comm = parts_.node->communication();
  s.heartbeat_ms = comm.heartbeat_ms;
  s.emcy_inhibit_100us = comm.emcy_inhibit_100us;
  for (uint8_t n = 0; n < kTpdoCount; ++n) s.tpdo[n] = comm.tpdo[n];
  for (uint8_t n = 0; n < kRpdoCount; ++n) s.rpdo[n] = comm.rpdo[n];
  return s;
}

void BoardObjects::UpdateSettingsPending() {
  // Any configuration edit not yet in force (stored and applied at the next reset). Compared on
  // the stored form, once per edit rather than on every read of 0x2122. The communication
  // parameters are the node's (in force as soon as written), so they take no part.
  const BoardSettings& in_force = *parts_.settings_in_force;
  BoardSettings edited = pending_;
  edited.heartbeat_ms = in_force.heartbeat_ms;
  edited.emcy_inhibit_100us = in_force.emcy_inhibit_100us;
  for (uint8_t n = 0; n < kTpdoCount; ++n) edited.tpdo[n] = in_force.tpdo[n];
  for (uint8_t n = 0; n < kRpdoCount; ++n) edited.rpdo[n] = in_force.rpdo[n];
  uint8_t a_bytes[kSettingsBytes], p_bytes[kSettingsBytes];
  SerializeSettings(in_force, a_bytes);
  SerializeSettings(edited, p_bytes);
  settings_pending_ = false;
  for (uint32_t i = 0; i < kSettingsBytes; ++i) {
    if (a_bytes[i] != p_bytes[i]) {
      settings_pending_ = true;
      break;
    }
  }
}

uint16_t BoardObjects::device_state() const {
  const ControlTick& t = *parts_.control_tick;
  const BoardPolicy& policy = *parts_.policy;
  canopen::DeviceState s;
  s.referenced = t.all_referenced();
  s.engaged = t.compensator().engaged();
  s.fault = policy.fault();
  s.writable = policy.writable();
  s.moving = policy.moving();
  s.table_active = policy.table_active();
  s.staged_verified = parts_.tables->staged_state() == StagedState::kVerified;
  s.passthrough = t.compensator().passthrough();
  s.settings_pending = settings_pending_;
  s.thermal_fault = parts_.thermal->fault();
  return canopen::EncodeDeviceState(s);
}

uint8_t BoardObjects::thermal_status() const {
  const thermal::ThermalStatus& t = parts_.thermal->correction().status();
  return static_cast<uint8_t>(
      (t.active ? canopen::kThermalActive : 0) | (t.holding ? canopen::kThermalHolding : 0) |
      (t.fading ? canopen::kThermalFading : 0) | (t.slewing ? canopen::kThermalSlewing : 0) |
      (parts_.thermal->saturated_axes() != 0 ? canopen::kThermalSaturated : 0));
}

namespace {
// Rounded to the nearest integer, saturated at int32 (main loop only: float is allowed here).
int32_t RoundToInt32(float v) {
  if (!(v > -2147483520.0f)) return INT32_MIN;  // NaN too
  if (v >= 2147483520.0f) return INT32_MAX;
  return static_cast<int32_t>(v >= 0.0f ? v + 0.5f : v - 0.5f);
}
}  // namespace

// Not inlined into each of the 12 per-axis value readers (flash: docs/mcu-target.md).
[[gnu::noinline]] int32_t BoardObjects::thermal_offset(uint8_t a) const {
  return a < axis_count() ? RoundToInt32(parts_.thermal->correction().applied_offset_um(a) * 1e3f)
                          : 0;
}

[[gnu::noinline]] int32_t BoardObjects::thermal_slope(uint8_t a) const {
  // um per mm = 1e6 nm per m.
  return a < axis_count()
             ? RoundToInt32(parts_.thermal->correction().applied_slope_um_per_mm(a) * 1e6f)
             : 0;
}

SdoAbort BoardObjects::WriteTemperature(uint8_t ch, uint32_t raw) {
  BoardThermal& t = *parts_.thermal;
  if (t.channels().config(ch).source != thermal::ChannelSource::kCanObject) {
    // Another source feeds the channel, or none: a reading is refused; "no reading" (0x8000, what
    // an RPDO carries for a channel its sender does not feed) is nothing to deliver.
    if (static_cast<int16_t>(raw & 0xFFFFu) == thermal::kNoReading_cC) return SdoAbort::kNone;
    return Refuse(SdoAbort::kReadOnly);
  }
  return t.Reading(ch, static_cast<int16_t>(raw & 0xFFFFu), parts_.policy->now_ms()).ok()
             ? SdoAbort::kNone
             : SdoAbort::kGeneral;
}

uint32_t BoardObjects::table_status() const {
  canopen::TableStatus s;
  s.staged = parts_.tables->staged_state();
  s.busy = s.staged == StagedState::kReceiving;
  s.error = parts_.tables->last_error();
  s.result = canopen::TableResultOf(s.error);
  return canopen::EncodeTableStatus(s);
}

void BoardObjects::WatchLimits(uint32_t now_ms) {
  now_ms_ = now_ms;
  const Compensator& c = parts_.control_tick->compensator();
  uint8_t clamped = 0, limited = 0;
  for (uint8_t a = 0; a < c.axis_count(); ++a) {
    const uint32_t n_clamped = c.clamped_refreshes(a), n_limited = c.rate_limited_refreshes(a);
    if (n_clamped != seen_clamped_[a]) clamped_at_ms_[a] = now_ms_;
    if (n_limited != seen_limited_[a]) limited_at_ms_[a] = now_ms_;
    seen_clamped_[a] = n_clamped;
    seen_limited_[a] = n_limited;
    const uint8_t bit = static_cast<uint8_t>(1u << a);
    const auto recent = [this](uint32_t count, uint32_t at_ms) {
      return count != 0 && static_cast<uint32_t>(now_ms_ - at_ms) < canopen::kLimitHoldMs;
    };
    if (recent(n_clamped, clamped_at_ms_[a])) clamped = static_cast<uint8_t>(clamped | bit);
    if (recent(n_limited, limited_at_ms_[a])) limited = static_cast<uint8_t>(limited | bit);
  }
  clamped_mask_ = clamped;
  limited_mask_ = limited;
  // One EMCY when a limitation starts on an axis: clamping at any time, rate limiting while the
  // axes move. Each is reported again only after it stopped (no count for kLimitHoldMs).
  const uint8_t limited_moving = parts_.policy->moving() ? limited : 0;
  const uint8_t new_clamped = static_cast<uint8_t>(clamped & ~reported_clamped_);
  const uint8_t new_limited = static_cast<uint8_t>(limited_moving & ~reported_limited_);
  reported_clamped_ = clamped;
  reported_limited_ = static_cast<uint8_t>((reported_limited_ | limited_moving) & limited);
  if ((new_clamped | new_limited) != 0) {
    const uint32_t detail = uint32_t{new_clamped} | uint32_t{new_limited} << 8;
    parts_.node->ReportEvent(canopen::kEmcyCorrectionLimited, canopen::kErrManufacturer, detail);
  }
}

uint8_t BoardObjects::correction_limited(uint8_t a) const {
  const uint8_t bit = static_cast<uint8_t>(1u << a);
  return static_cast<uint8_t>(((clamped_mask_ & bit) != 0 ? canopen::kLimitClamped : 0) |
                              ((limited_mask_ & bit) != 0 ? canopen::kLimitRateLimited : 0));
}

int16_t BoardObjects::correction_steps(uint8_t a) const {
  const int64_t q8 = applied_correction(a);
  const int64_t steps = q8 >= 0 ? (q8 + 128) / 256 : -((-q8 + 128) / 256);
  return static_cast<int16_t>(steps > 32767 ? 32767 : steps < -32767 ? -32767 : steps);
}

uint32_t BoardObjects::settings_check() const {
  canopen::SettingsCheck c;
  c.error = ValidateSettings(WithCommunication(pending_), &c.finding, parts_.output_stage).error();
  return canopen::EncodeSettingsCheck(c);
}

SdoAbort BoardObjects::Refuse(SdoAbort abort_code) {
  ++refused_;
  parts_.node->ReportEvent(canopen::kEmcyRefused, 0, canopen::Code(abort_code));
  return abort_code;
}

bool BoardObjects::ReadNumber(const ObjectEntry& e, uint32_t* v) const {
  if (const canopen::SettingObject* s = canopen::FindSetting(e.id); s != nullptr) {
    *v = static_cast<uint32_t>(s->get(pending_));
    return true;
  }
  if (const ValueRead read = kValues[static_cast<size_t>(e.id)]; read != nullptr) {
    *v = read(*this);
    return true;
  }
  if (canopen::FixedSize(e.type) != 0 && canopen::Readable(e.access)) {
    *v = static_cast<uint32_t>(e.default_value);  // a fixed value (VOLCOMP_OD_ENTRY)
    return true;
  }
  return false;
}

SdoAbort BoardObjects::DoRead(const ObjectEntry& e,
                              uint32_t offset,
                              uint8_t* buf,
                              uint32_t cap,
                              uint32_t* copied,
                              uint32_t* total) {
  const TableStore& tables = *parts_.tables;
  switch (e.id) {
    case ObjectId::kDeviceName:
      return CopyOut(reinterpret_cast<const uint8_t*>(identity_.device_name),
                     StringLength(identity_.device_name), offset, buf, cap, copied, total);
    case ObjectId::kHardwareVersion:
      return CopyOut(reinterpret_cast<const uint8_t*>(identity_.hardware_version),
                     StringLength(identity_.hardware_version), offset, buf, cap, copied, total);
    case ObjectId::kSoftwareVersion:
      return CopyOut(reinterpret_cast<const uint8_t*>(identity_.software_version),
                     StringLength(identity_.software_version), offset, buf, cap, copied, total);
    case ObjectId::kSettingsInForce: {
      // What the board runs with (the settings applied at the last start or reset node, the
      // communication parameters in force), in the stored record's format: the reader decodes it
      // with DeserializeSettings, the same code as the settings store.
      uint8_t record[kSettingsBytes];
      SerializeSettings(WithCommunication(*parts_.settings_in_force), record);
      return CopyOut(record, kSettingsBytes, offset, buf, cap, copied, total);
    }
    case ObjectId::kActiveTableData:
      // The active image (read-back for verification of what compensates).
      if (parts_.policy->table_active() && tables.active_data() != nullptr) {
        return CopyOut(tables.active_data(), tables.active_size(), offset, buf, cap, copied, total);
      }
      return SdoAbort::kNoData;
    case ObjectId::kTableData: {
      // The staged image while one is staged, else the active one (read-back for verification).
      const StagedState st = tables.staged_state();
      if (st != StagedState::kEmpty && st != StagedState::kReceiving &&
          tables.staged_data() != nullptr) {
        return CopyOut(tables.staged_data(), tables.staged_bytes(), offset, buf, cap, copied,
                       total);
      }
      if (parts_.policy->table_active() && tables.active_data() != nullptr) {
        return CopyOut(tables.active_data(), tables.active_size(), offset, buf, cap, copied, total);
      }
      return SdoAbort::kNoData;
    }
    default:
      break;
  }
  uint32_t v = 0;
  if (!ReadNumber(e, &v)) return SdoAbort::kNoObject;
  uint8_t bytes[4];
  StoreLe32(bytes, v);
  return CopyOut(bytes, canopen::FixedSize(e.type), offset, buf, cap, copied, total);
}

SdoAbort BoardObjects::WriteSetting(const ObjectEntry& e, uint32_t raw) {
  const canopen::SettingObject& s = *canopen::FindSetting(e.id);
  const int64_t v = canopen::EntryValue(e, raw);
  if (e.limited && (v < e.low_limit || v > e.high_limit)) {
    if (s.enumerated) return SdoAbort::kInvalidValue;
    return v < e.low_limit ? SdoAbort::kValueTooLow : SdoAbort::kValueTooHigh;
  }
  // Single fields are range-checked here; the whole configuration is checked at "store" (0x1010),
  // which refuses an inconsistent set with 0x06090030.
  s.set(pending_, v);
  UpdateSettingsPending();
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::TableControl(uint8_t command) {
  last_command_ = command;
  BoardPolicy& policy = *parts_.policy;
  TableStore& tables = *parts_.tables;
  const BoardConfig& board = parts_.settings_in_force->board;
  using canopen::TableCommand;
  switch (static_cast<TableCommand>(command)) {
    case TableCommand::kVerify: {
      // CiA 301 7.2.4.3.17 (docs/canopen.md, "Rules that protect the machine"): the command value
      // is valid, the staged data are not: nothing to verify is "no data available", an upload
      // in progress "the present device state", an image that fails the checks "data cannot be
      // transferred or stored to the application" (with EMCY 0x6300 and the error in 0x2102).
      const StagedState staged = tables.staged_state();
      if (staged == StagedState::kReceiving) return Refuse(SdoAbort::kDeviceState);
      if (staged != StagedState::kComplete && staged != StagedState::kVerified) {
        return Refuse(SdoAbort::kNoData);
      }
      const Status s = tables.Verify(board);
      if (!s.ok()) {
        parts_.node->ReportEvent(canopen::kEmcyTableInvalid, canopen::kErrManufacturer,
                                 static_cast<uint32_t>(s.error()));
        return SdoAbort::kCannotStore;
      }
      return SdoAbort::kNone;
    }
    case TableCommand::kClear:
      if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
      tables.Clear();
      return SdoAbort::kNone;
    case TableCommand::kDeactivate:
      if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
      if (!tables.Deactivate().ok()) return Refuse(SdoAbort::kHardware);
      policy.Deactivate();
      return SdoAbort::kNone;
    case TableCommand::kActivate: {
      if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
      if (tables.staged_state() == StagedState::kComplete) (void)tables.Verify(board);
      if (tables.staged_state() != StagedState::kVerified) return Refuse(SdoAbort::kNoData);
      if (const SdoAbort why = policy.MayActivate(); why != SdoAbort::kNone) return Refuse(why);
      const Result<table::TableView> view = tables.Activate();
      if (!view.ok()) return Refuse(SdoAbort::kHardware);
      if (!policy.Activate(*view).ok()) return Refuse(SdoAbort::kGeneral);
      return SdoAbort::kNone;
    }
  }
  return SdoAbort::kInvalidValue;
}

SdoAbort BoardObjects::CommandWord(uint16_t word) {
  using canopen::kCommandActivate;
  using canopen::kCommandDeactivate;
  const uint16_t rising = static_cast<uint16_t>(word & ~command_word_);
  if ((word & ~canopen::kCommandWordBits) != 0 ||
      (rising & (kCommandActivate | kCommandDeactivate)) ==
          (kCommandActivate | kCommandDeactivate)) {
    return Refuse(SdoAbort::kInvalidValue);
  }
  command_word_ = word;
  if ((rising & canopen::kCommandReferenceMask) != 0) {
    parts_.policy->RequestReference(static_cast<uint8_t>(rising & canopen::kCommandReferenceMask));
  }
  if ((rising & kCommandDeactivate) != 0) {
    return TableControl(static_cast<uint8_t>(canopen::TableCommand::kDeactivate));
  }
  if ((rising & kCommandActivate) != 0) {
    return TableControl(static_cast<uint8_t>(canopen::TableCommand::kActivate));
  }
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::StoreSettings() {
  // "Save all parameters" includes the communication parameters in force (0x1015, 0x1017, the
  // TPDOs' 0x1800+n / 0x1A00+n): they
  // become what the resets restore.
  const BoardSettings s = WithCommunication(pending_);
  if (!ValidateSettings(s, nullptr, parts_.output_stage).ok()) return SdoAbort::kInvalidValue;
  if (!parts_.settings_store->Save(s).ok()) return Refuse(SdoAbort::kHardware);
  parts_.node->set_stored_communication(CommunicationOf(s));
  UpdateSettingsPending();
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
  uint32_t v = 0;
  for (uint32_t i = 0; i < size && i < 4; ++i) v |= uint32_t{data[i]} << (8 * i);
  BoardPolicy& policy = *parts_.policy;
  switch (e.id) {
    case ObjectId::kUnlock:
      if (const SdoAbort r = policy.WriteUnlock(v); r != SdoAbort::kNone) return Refuse(r);
      return SdoAbort::kNone;
    case ObjectId::kReferenceAxes:
      policy.RequestReference(static_cast<uint8_t>(v));
      return SdoAbort::kNone;
    case ObjectId::kCompensationEnable:
      if (v > 1) return SdoAbort::kInvalidValue;
      policy.SetBusEnable(v == 1);
      return SdoAbort::kNone;
    case ObjectId::kTableControl:
      return TableControl(static_cast<uint8_t>(v));
    case ObjectId::kCommandWord:
      return CommandWord(static_cast<uint16_t>(v));
    case ObjectId::kTemperature1:
    case ObjectId::kTemperature2:
    case ObjectId::kTemperature3:
    case ObjectId::kTemperature4:
    case ObjectId::kTemperature5:
    case ObjectId::kTemperature6:
    case ObjectId::kTemperature7:
    case ObjectId::kTemperature8:
      return WriteTemperature(static_cast<uint8_t>(static_cast<uint16_t>(e.id) -
                                                   static_cast<uint16_t>(ObjectId::kTemperature1)),
                              v);
    case ObjectId::kStoreAll:
      if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
      if (v != canopen::kSaveSignature) return SdoAbort::kCannotStore;
      return StoreSettings();
    case ObjectId::kRestoreAll:
      if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
      if (v != canopen::kLoadSignature) return SdoAbort::kCannotStore;
      if (!parts_.settings_store->Reset().ok()) return Refuse(SdoAbort::kHardware);
      // CiA 301: the defaults take effect at the next reset, the communication reset included.
      parts_.node->set_stored_communication(canopen::CommunicationParameters{});
      return SdoAbort::kNone;
    default:
      break;
  }
  if (canopen::FindSetting(e.id) != nullptr) {
    if (!policy.writable()) return Refuse(SdoAbort::kCannotStore);
    return WriteSetting(e, v);
  }
  return SdoAbort::kReadOnly;
}

SdoAbort BoardObjects::DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) {
  if (e.id != ObjectId::kTableData) return SdoAbort::kUnsupportedAccess;
  if (!parts_.policy->writable()) return Refuse(SdoAbort::kCannotStore);
  transfer_abort_ = SdoAbort::kNone;
  if (size > parts_.tables->capacity()) return SdoAbort::kTooLong;
  if (!parts_.tables->BeginUpload(size).ok()) return Refuse(SdoAbort::kHardware);
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::DoDomainWriteData(const uint8_t* data, uint32_t size) {
  const Status s = parts_.tables->UploadData(data, size);
  if (s.ok()) return SdoAbort::kNone;
  return s.error() == Error::kImageTooLarge ? SdoAbort::kTooLong : SdoAbort::kHardware;
}

SdoAbort BoardObjects::DoDomainWriteFlush(bool* done) {
  return parts_.tables->FlushUpload(done).ok() ? SdoAbort::kNone : SdoAbort::kHardware;
}

SdoAbort BoardObjects::DoEndDomainWrite(SdoAbort outcome, canopen::AbortOrigin origin) {
  if (canopen::Failed(outcome)) {
    // The transfer broke: 0x2102 says how (aborted by the board or by the client, CRC-16,
    // timeout), not "I/O error"; 0x210A keeps the abort code.
    transfer_abort_ = outcome;
    parts_.tables->AbandonUpload(canopen::TransferError(outcome, origin));
    return SdoAbort::kNone;
  }
  const Status s = parts_.tables->FinishUpload();
  if (s.ok()) return SdoAbort::kNone;
  if (s.error() != Error::kImageSizeMismatch) return SdoAbort::kHardware;
  // Fewer or more bytes than announced (the SDO server checks this first; kept for any path).
  return parts_.tables->staged_bytes() < parts_.tables->expected_size() ? SdoAbort::kTooShort
                                                                        : SdoAbort::kTooLong;
}

uint32_t BoardObjects::transfer_abort_code() const {
  switch (parts_.tables->last_error()) {
    case Error::kTransferAborted:
    case Error::kTransferAbortedByClient:
    case Error::kTransferCrcMismatch:
    case Error::kTransferTimeout:
    case Error::kImageSizeMismatch:
      return canopen::Code(transfer_abort_);
    default:
      return 0;
  }
}

}  // namespace volcomp::firmware
