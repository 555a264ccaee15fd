// The board's object dictionary values.
#include "volcomp/firmware/board_objects.hpp"

#include <type_traits>
#include <utility>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

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

// The configuration entries' fields in BoardSettings, one accessor pair per dictionary entry (null
// for entries that are not settings), expanded from the bindings in od_entries.def.
struct FieldAccess {
  int64_t (*get)(const BoardSettings& s);
  void (*set)(BoardSettings& s, int64_t value);
  bool enumerated;  // an enum field: out-of-range values are invalid, not too high or too low
};

template <class T>
constexpr int64_t FieldValue(T v) {
  if constexpr (std::is_enum_v<T>) {
    return static_cast<int64_t>(static_cast<std::underlying_type_t<T>>(v));
  } else {
    return static_cast<int64_t>(v);
  }
}

template <class T>
constexpr void SetField(T& field, int64_t v) {
  field = static_cast<T>(v);
}

#define VOLCOMP_OD_OBJECT(index, kind, name)
#define VOLCOMP_OD_ENTRY(id, index, sub, type, access, def, name) {nullptr, nullptr, false},
#define VOLCOMP_OD_SETTING(id, index, sub, type, limits, def, field, name) \
  {[](const BoardSettings& s) { return FieldValue(s.field); },             \
   [](BoardSettings& s, int64_t v) { SetField(s.field, v); },              \
   std::is_enum_v<std::remove_reference_t<decltype(std::declval<BoardSettings&>().field)>>},
constexpr FieldAccess kFields[] = {
#include "volcomp/canopen/od_entries.def"  // NOLINT(build/include)
};
#undef VOLCOMP_OD_OBJECT
#undef VOLCOMP_OD_ENTRY
#undef VOLCOMP_OD_SETTING
static_assert(sizeof(kFields) / sizeof(kFields[0]) == static_cast<size_t>(ObjectId::kCount),
              "one field access per ObjectId");

const FieldAccess& Field(const ObjectEntry& e) { return kFields[static_cast<size_t>(e.id)]; }

// The value of a write to `e` as a number of its type (sign-extended for the signed types).
int64_t WrittenValue(const ObjectEntry& e, uint32_t raw) {
  switch (e.type) {
    case canopen::DataType::kInteger8:
      return static_cast<int8_t>(raw);
    case canopen::DataType::kInteger16:
      return static_cast<int16_t>(raw);
    case canopen::DataType::kInteger32:
      return static_cast<int32_t>(raw);
    default:
      return raw;
  }
}

// The axis (0-based) of `id` in the per-axis array whose axis-1 entry is `first`, if it is one.
bool AxisOf(ObjectId id, ObjectId first, uint8_t* axis) {
  const int d = static_cast<int>(id) - static_cast<int>(first);
  if (d < 0 || d >= static_cast<int>(table::kMaxAxes)) return false;
  *axis = static_cast<uint8_t>(d);
  return true;
}

}  // namespace

BoardObjects::BoardObjects(BoardControl* control,
                           TableStore* tables,
                           SettingsStore* settings_store,
                           canopen::Node* node,
                           const IdentityInfo& identity)
    : control_(control),
      tables_(tables),
      settings_store_(settings_store),
      node_(node),
      identity_(identity) {}

void BoardObjects::SetSettings(const BoardSettings& active) {
  active_ = active;
  pending_ = active;
  settings_pending_ = false;
}

void BoardObjects::UpdateSettingsPending() {
  // Any configuration edit not yet in force (stored and applied at the next reset). Compared on
  // the stored form, once per edit rather than on every read of 0x2122.
  uint8_t a_bytes[kSettingsBytes], p_bytes[kSettingsBytes];
  SerializeSettings(active_, a_bytes);
  SerializeSettings(pending_, p_bytes);
  settings_pending_ = false;
  for (uint32_t i = 0; i < kSettingsBytes; ++i) {
    if (a_bytes[i] != p_bytes[i]) {
      settings_pending_ = true;
      break;
    }
  }
}

bool BoardObjects::writable() const {
  const bool unlocked = unlocked_ && static_cast<uint32_t>(now_ms_ - unlocked_at_ms_) < kUnlockMs;
  return control_->write_enable_input() || unlocked;
}

uint16_t BoardObjects::device_state() const {
  const ControlTick& e = control_->control_tick();
  canopen::DeviceState s;
  s.referenced = e.all_referenced();
  s.engaged = e.compensator().engaged();
  s.fault = control_->fault();
  s.writable = writable();
  s.moving = control_->moving();
  s.table_active = has_active_;
  s.staged_verified = tables_->staged_state() == StagedState::kVerified;
  s.passthrough = e.compensator().passthrough();
  s.settings_pending = settings_pending_;
  return canopen::EncodeDeviceState(s);
}

uint32_t BoardObjects::table_status() const {
  canopen::TableStatus s;
  s.staged = tables_->staged_state();
  s.busy = s.staged == StagedState::kReceiving;
  s.error = tables_->last_error();
  s.result = canopen::TableResultOf(s.error);
  return canopen::EncodeTableStatus(s);
}

void BoardObjects::WatchLimits() {
  const Compensator& c = control_->control_tick().compensator();
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
  const uint8_t limited_moving = control_->moving() ? limited : 0;
  const uint8_t new_clamped = static_cast<uint8_t>(clamped & ~reported_clamped_);
  const uint8_t new_limited = static_cast<uint8_t>(limited_moving & ~reported_limited_);
  reported_clamped_ = clamped;
  reported_limited_ = static_cast<uint8_t>((reported_limited_ | limited_moving) & limited);
  if ((new_clamped | new_limited) != 0) {
    const uint32_t detail = uint32_t{new_clamped} | uint32_t{new_limited} << 8;
    node_->ReportEvent(canopen::kEmcyCorrectionLimited, canopen::kErrManufacturer, detail);
  }
}

uint8_t BoardObjects::limit_flags(uint8_t a) const {
  const uint8_t bit = static_cast<uint8_t>(1u << a);
  return static_cast<uint8_t>(((clamped_mask_ & bit) != 0 ? canopen::kLimitClamped : 0) |
                              ((limited_mask_ & bit) != 0 ? canopen::kLimitRateLimited : 0));
}

uint32_t BoardObjects::settings_check() const {
  BoardSettings s = pending_;
  const canopen::CommunicationParameters comm = node_->communication();
  s.heartbeat_ms = comm.heartbeat_ms;
  s.emcy_inhibit_100us = comm.emcy_inhibit_100us;
  canopen::SettingsCheck c;
  c.error = ValidateSettings(s, &c.finding).error();
  return canopen::EncodeSettingsCheck(c);
}

SdoAbort BoardObjects::Refuse(SdoAbort abort_code) {
  ++refused_;
  node_->ReportEvent(canopen::kEmcyRefused, 0, canopen::Code(abort_code));
  return abort_code;
}

bool BoardObjects::ReadNumber(const ObjectEntry& e, uint32_t* v) const {
  const ControlTick& tick = control_->control_tick();
  if (const FieldAccess& f = Field(e); f.get != nullptr) {
    *v = static_cast<uint32_t>(f.get(pending_));
    return true;
  }
  switch (e.id) {
    case ObjectId::kDeviceType:
      *v = 0;
      return true;
    case ObjectId::kVendorId:
    case ObjectId::kProductCode:
    case ObjectId::kRevision:
      *v = static_cast<uint32_t>(e.default_value);
      return true;
    case ObjectId::kSerialNumber:
      *v = identity_.serial_number;
      return true;
    case ObjectId::kStoreAll:
      *v = 1;
      return true;  // saves on command
    case ObjectId::kRestoreAll:
      *v = 1;
      return true;  // restores on command
    case ObjectId::kTableControl:
      *v = last_command_;
      return true;
    case ObjectId::kTableStatus:
      *v = table_status();
      return true;
    case ObjectId::kActiveTableId:
      *v = has_active_ ? active_id_ : 0;
      return true;
    case ObjectId::kActiveTableCrc:
      *v = has_active_ ? active_crc_ : 0;
      return true;
    case ObjectId::kStagedTableCrc:
      *v = tables_->staged_crc32();
      return true;
    case ObjectId::kStagedBytes:
      *v = tables_->staged_bytes();
      return true;
    case ObjectId::kStagedTableId:
      *v = tables_->staged_table_id();
      return true;
    case ObjectId::kTableBankSize:
      *v = tables_->capacity();
      return true;
    case ObjectId::kWriteAccess:
      *v = writable() ? 1 : 0;
      return true;
    case ObjectId::kCompensationEnable:
      *v = control_->bus_enable() ? 1 : 0;
      return true;
    case ObjectId::kDeviceState:
      *v = device_state();
      return true;
    case ObjectId::kCanRxFrames:
      *v = rx_frames_;
      return true;
    case ObjectId::kCanTxFrames:
      *v = tx_frames_;
      return true;
    case ObjectId::kMalformedFrames:
      *v = node_->malformed();
      return true;
    case ObjectId::kSdoAborts:
      *v = node_->sdo().aborts();
      return true;
    case ObjectId::kEmcySent:
      *v = node_->emcy_sent();
      return true;
    case ObjectId::kTicks:
      *v = static_cast<uint32_t>(tick.ticks());
      return true;
    case ObjectId::kOutputOverruns:
      *v = control_->output_status().overruns;
      return true;
    case ObjectId::kMaxTickCost:
      *v = control_->max_tick_cost_ns();
      return true;
    case ObjectId::kRefusedActions:
      *v = refused_;
      return true;
    case ObjectId::kEmcySuppressed:
      *v = node_->emcy_suppressed();
      return true;
    case ObjectId::kSettingsCheck:
      *v = settings_check();
      return true;
    default:
      break;
  }
  // Live per-axis values; axes that are not configured read 0.
  uint8_t a = 0;
  if (AxisOf(e.id, ObjectId::kCommandedPosition1, &a)) {
    *v = a < tick.axis_count() ? static_cast<uint32_t>(tick.commanded(a)) : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kMachinePosition1, &a)) {  // the table's coordinate
    *v = a < tick.axis_count() ? static_cast<uint32_t>(tick.machine_position(a)) : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kAppliedCorrection1, &a)) {
    *v = a < tick.axis_count() ? static_cast<uint32_t>(tick.compensator().applied_q8(a)) : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kOutputPosition1, &a)) {
    *v = a < tick.axis_count() ? static_cast<uint32_t>(control_->output_status().position_steps[a])
                              : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kMaxBacklog1, &a)) {
    *v = a < tick.axis_count() ? control_->output_status().max_backlog_steps[a] : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kCorrectionLimited1, &a)) {
    *v = a < tick.axis_count() ? limit_flags(a) : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kClampedRefreshes1, &a)) {
    *v = a < tick.axis_count() ? tick.compensator().clamped_refreshes(a) : 0;
    return true;
  }
  if (AxisOf(e.id, ObjectId::kRateLimitedRefreshes1, &a)) {
    *v = a < tick.axis_count() ? tick.compensator().rate_limited_refreshes(a) : 0;
    return true;
  }
  if (e.access == canopen::Access::kConst) {
    *v = static_cast<uint32_t>(e.default_value);
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
      BoardSettings s = active_;
      const canopen::CommunicationParameters comm = node_->communication();
      s.heartbeat_ms = comm.heartbeat_ms;
      s.emcy_inhibit_100us = comm.emcy_inhibit_100us;
      uint8_t record[kSettingsBytes];
      SerializeSettings(s, record);
      return CopyOut(record, kSettingsBytes, offset, buf, cap, copied, total);
    }
    case ObjectId::kActiveTableData:
      // The active image (read-back for verification of what compensates).
      if (has_active_ && tables_->active_data() != nullptr) {
        return CopyOut(tables_->active_data(), tables_->active_size(), offset, buf, cap, copied,
                       total);
      }
      return SdoAbort::kNoData;
    case ObjectId::kTableData: {
      // The staged image while one is staged, else the active one (read-back for verification).
      const StagedState st = tables_->staged_state();
      if (st != StagedState::kEmpty && st != StagedState::kReceiving &&
          tables_->staged_data() != nullptr) {
        return CopyOut(tables_->staged_data(), tables_->staged_bytes(), offset, buf, cap, copied,
                       total);
      }
      if (has_active_ && tables_->active_data() != nullptr) {
        return CopyOut(tables_->active_data(), tables_->active_size(), offset, buf, cap, copied,
                       total);
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
  const FieldAccess& f = Field(e);
  const int64_t v = WrittenValue(e, raw);
  if (e.limited && (v < e.low_limit || v > e.high_limit)) {
    if (f.enumerated) return SdoAbort::kInvalidValue;
    return v < e.low_limit ? SdoAbort::kValueTooLow : SdoAbort::kValueTooHigh;
  }
  // Single fields are range-checked here; the whole configuration is checked at "store" (0x1010),
  // which refuses an inconsistent set with 0x06090030.
  f.set(pending_, v);
  UpdateSettingsPending();
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::TableControl(uint8_t command) {
  last_command_ = command;
  const BoardConfig& board = active_.board;
  using canopen::TableCommand;
  switch (static_cast<TableCommand>(command)) {
    case TableCommand::kVerify: {
      const Status s = tables_->Verify(board);
      if (!s.ok()) {
        node_->ReportEvent(canopen::kEmcyTableInvalid, canopen::kErrManufacturer,
                           static_cast<uint32_t>(s.error()));
        return SdoAbort::kInvalidValue;
      }
      return SdoAbort::kNone;
    }
    case TableCommand::kClear:
      if (!writable()) return Refuse(SdoAbort::kCannotStore);
      tables_->Clear();
      return SdoAbort::kNone;
    case TableCommand::kDeactivate:
      if (!writable()) return Refuse(SdoAbort::kCannotStore);
      if (!tables_->Deactivate().ok()) return Refuse(SdoAbort::kHardware);
      control_->RequestClearTable();
      clear_active();
      return SdoAbort::kNone;
    case TableCommand::kActivate: {
      if (!writable()) return Refuse(SdoAbort::kCannotStore);
      if (tables_->staged_state() == StagedState::kComplete) (void)tables_->Verify(board);
      if (tables_->staged_state() != StagedState::kVerified) return Refuse(SdoAbort::kNoData);
      if (!control_->control_tick().all_referenced() || control_->moving()) {
        return Refuse(SdoAbort::kDeviceState);
      }
      const Result<table::TableView> view = tables_->Activate();
      if (!view.ok()) return Refuse(SdoAbort::kHardware);
      if (!control_->ActivateTable(*view).ok()) return Refuse(SdoAbort::kGeneral);
      return SdoAbort::kNone;
    }
  }
  return SdoAbort::kInvalidValue;
}

SdoAbort BoardObjects::StoreSettings() {
  // "Save all parameters" includes the communication parameters in force (0x1015, 0x1017): they
  // become what the resets restore.
  const canopen::CommunicationParameters comm = node_->communication();
  BoardSettings s = pending_;
  s.heartbeat_ms = comm.heartbeat_ms;
  s.emcy_inhibit_100us = comm.emcy_inhibit_100us;
  if (!ValidateSettings(s).ok()) return SdoAbort::kInvalidValue;
  if (!settings_store_->Save(s).ok()) return Refuse(SdoAbort::kHardware);
  pending_.heartbeat_ms = active_.heartbeat_ms = comm.heartbeat_ms;
  pending_.emcy_inhibit_100us = active_.emcy_inhibit_100us = comm.emcy_inhibit_100us;
  UpdateSettingsPending();
  node_->set_stored_communication(comm);
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
  uint32_t v = 0;
  for (uint32_t i = 0; i < size && i < 4; ++i) v |= uint32_t{data[i]} << (8 * i);
  switch (e.id) {
    case ObjectId::kUnlock:
      if (v == canopen::kUnlockSignature) {
        unlocked_ = true;
        unlocked_at_ms_ = now_ms_;
        return SdoAbort::kNone;
      }
      unlocked_ = false;  // any other value locks
      return v == 0 ? SdoAbort::kNone : Refuse(SdoAbort::kInvalidValue);
    case ObjectId::kReferenceAxes:
      control_->RequestReference(static_cast<uint8_t>(v));
      return SdoAbort::kNone;
    case ObjectId::kCompensationEnable:
      if (v > 1) return SdoAbort::kInvalidValue;
      control_->SetBusEnable(v == 1);
      return SdoAbort::kNone;
    case ObjectId::kTableControl:
      return TableControl(static_cast<uint8_t>(v));
    case ObjectId::kStoreAll:
      if (!writable()) return Refuse(SdoAbort::kCannotStore);
      if (v != canopen::kSaveSignature) return SdoAbort::kCannotStore;
      return StoreSettings();
    case ObjectId::kRestoreAll:
      if (!writable()) return Refuse(SdoAbort::kCannotStore);
      if (v != canopen::kLoadSignature) return SdoAbort::kCannotStore;
      if (!settings_store_->Reset().ok()) return Refuse(SdoAbort::kHardware);
      // CiA 301: the defaults take effect at the next reset, the communication reset included.
      node_->set_stored_communication(canopen::CommunicationParameters{});
      return SdoAbort::kNone;
    default:
      break;
  }
  if (Field(e).set != nullptr) {
    if (!writable()) return Refuse(SdoAbort::kCannotStore);
    return WriteSetting(e, v);
  }
  return SdoAbort::kReadOnly;
}

SdoAbort BoardObjects::DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) {
  if (e.id != ObjectId::kTableData) return SdoAbort::kUnsupportedAccess;
  if (!writable()) return Refuse(SdoAbort::kCannotStore);
  if (size > tables_->capacity()) return SdoAbort::kTooLong;
  if (!tables_->BeginUpload(size).ok()) return Refuse(SdoAbort::kHardware);
  return SdoAbort::kNone;
}

SdoAbort BoardObjects::DoDomainWriteData(const uint8_t* data, uint32_t size) {
  const Status s = tables_->UploadData(data, size);
  if (s.ok()) return SdoAbort::kNone;
  return s.error() == Error::kImageTooLarge ? SdoAbort::kTooLong : SdoAbort::kHardware;
}

SdoAbort BoardObjects::DoDomainWriteFlush(bool* done) {
  return tables_->FlushUpload(done).ok() ? SdoAbort::kNone : SdoAbort::kHardware;
}

SdoAbort BoardObjects::DoEndDomainWrite(SdoAbort outcome) {
  if (canopen::Failed(outcome)) {
    // The transfer broke: 0x2102 says how (aborted, CRC-16, timeout), not "I/O error".
    tables_->AbandonUpload(canopen::TransferError(outcome));
    return SdoAbort::kNone;
  }
  const Status s = tables_->FinishUpload();
  if (s.ok()) return SdoAbort::kNone;
  return s.error() == Error::kImageSizeMismatch ? SdoAbort::kTypeMismatch : SdoAbort::kHardware;
}

}  // namespace volcomp::firmware
