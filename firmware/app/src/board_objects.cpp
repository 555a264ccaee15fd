// The board's object dictionary values.
#include "volcomp/firmware/board_objects.hpp"

#include "volcomp/byte_order.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::firmware {
namespace {

using canopen::ObjectEntry;
using canopen::ObjectId;

uint32_t CopyOut(const uint8_t* src,
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
  return 0;
}

uint32_t StringLength(const char* s) {
  uint32_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

// The uint32 field of an axis configuration behind a per-axis object index, or null.
uint32_t* AxisU32(AxisConfig& a, uint16_t index) {
  switch (index) {
    case 0x2012:
      return &a.resolution_e9;
    case 0x2016:
      return &a.max_correction_rate_steps_s;
    case 0x2017:
      return &a.max_correction_accel_steps_s2;
    case 0x2019:
      return &a.drive.pulse_width_ns;
    case 0x201A:
      return &a.drive.step_space_ns;
    case 0x201B:
      return &a.drive.dir_setup_ns;
    case 0x201C:
      return &a.drive.dir_hold_ns;
    case 0x201D:
      return &a.drive.max_rate_hz;
    case 0x201E:
      return &a.max_input_rate_hz;
    default:
      return nullptr;
  }
}

// Per-axis configuration objects 0x2010..0x201E, sub 1..6.
bool IsAxisConfig(const ObjectEntry& e) {
  return e.index >= 0x2010 && e.index <= 0x201E && e.sub >= 1 && e.sub <= table::kMaxAxes;
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
}

bool BoardObjects::writable() const {
  const bool unlocked = unlocked_ && static_cast<uint32_t>(now_ms_ - unlocked_at_ms_) < kUnlockMs;
  return control_->write_enable_input() || unlocked;
}

uint16_t BoardObjects::device_state() const {
  const ControlTick& e = control_->engine();
  uint16_t s = 0;
  if (e.all_referenced()) s |= kStateReferenced;
  if (e.compensator().engaged()) s |= kStateEngaged;
  if (control_->fault()) s |= kStateFault;
  if (writable()) s |= kStateWritable;
  if (control_->moving()) s |= kStateMoving;
  if (has_active_) s |= kStateTableActive;
  if (tables_->staged_state() == StagedState::kVerified) s |= kStateStagedVerified;
  if (e.compensator().passthrough()) s |= kStatePassthrough;
  // Any configuration edit not yet in force (stored and applied at the next reset).
  uint8_t a_bytes[kSettingsBytes], p_bytes[kSettingsBytes];
  SerializeSettings(active_, a_bytes);
  SerializeSettings(pending_, p_bytes);
  for (uint32_t i = 0; i < kSettingsBytes; ++i) {
    if (a_bytes[i] != p_bytes[i]) {
      s |= kStateSettingsPending;
      break;
    }
  }
  return s;
}

uint32_t BoardObjects::table_status() const {
  const StagedState st = tables_->staged_state();
  const uint32_t busy = st == StagedState::kReceiving ? 1u : 0u;
  uint32_t result = 0;  // 0 ok
  switch (tables_->last_error()) {
    case Error::kOk:
      result = 0;
      break;
    case Error::kImageBadCrc:
      result = 3;
      break;
    case Error::kConfigAxisMismatch:
    case Error::kConfigResolutionMismatch:
    case Error::kConfigTooManyAxes:
      result = 4;
      break;
    case Error::kIoError:
      result = 5;
      break;
    case Error::kImageTooLarge:
      result = 6;
      break;
    default:
      result = 2;
      break;  // format error
  }
  return busy | (result << 1) | (static_cast<uint32_t>(st) << 8) |
         (static_cast<uint32_t>(tables_->last_error()) << 16);
}

uint32_t BoardObjects::Refuse(uint32_t abort_code) {
  ++refused_;
  node_->ReportEvent(kEmcyRefused, 0, abort_code);
  return abort_code;
}

bool BoardObjects::ReadNumber(const ObjectEntry& e, uint32_t* v) const {
  const ControlTick& eng = control_->engine();
  const BoardSettings& p = pending_;
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
    case ObjectId::kNodeIdConfig:
      *v = p.node_id;
      return true;
    case ObjectId::kBitrateConfig:
      *v = p.bitrate_kbit;
      return true;
    case ObjectId::kTickRateConfig:
      *v = p.board.tick_hz;
      return true;
    case ObjectId::kAxisCountConfig:
      *v = p.board.axis_count;
      return true;
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
      *v = static_cast<uint32_t>(eng.ticks());
      return true;
    case ObjectId::kLostStepChecks:
      *v = control_->output_status().overruns;
      return true;
    case ObjectId::kMaxTickCost:
      *v = control_->max_tick_cost_ns();
      return true;
    case ObjectId::kRefusedActions:
      *v = refused_;
      return true;
    default:
      break;
  }
  if (IsAxisConfig(e)) {
    AxisConfig x = p.board.axis[e.sub - 1];
    switch (e.index) {
      case 0x2010:
        *v = static_cast<uint8_t>(x.name);
        return true;
      case 0x2011:
        *v = static_cast<uint8_t>(x.kind);
        return true;
      case 0x2013:
        *v = static_cast<uint8_t>(x.input_format);
        return true;
      case 0x2014:
        *v = static_cast<uint8_t>(x.output_format);
        return true;
      case 0x2015:
        *v = static_cast<uint32_t>(x.max_correction_steps);
        return true;
      case 0x2018:
        *v = static_cast<uint32_t>(x.home_position_steps);
        return true;
      default:
        *v = *AxisU32(x, e.index);
        return true;
    }
  }
  if (e.index >= 0x2130 && e.index <= 0x2133 && e.sub >= 1) {
    const uint8_t a = static_cast<uint8_t>(e.sub - 1);
    *v = 0;
    if (a >= eng.axis_count()) return true;  // axes not configured read 0
    switch (e.index) {
      case 0x2130:
        *v = static_cast<uint32_t>(eng.commanded(a));
        break;
      case 0x2131:
        *v = static_cast<uint32_t>(eng.compensator().applied_q8(a));
        break;
      case 0x2132:
        *v = static_cast<uint32_t>(control_->output_status().position_steps[a]);
        break;
      default:
        *v = control_->output_status().max_backlog_steps[a];
        break;
    }
    return true;
  }
  if (e.access == canopen::Access::kConst) {
    *v = static_cast<uint32_t>(e.default_value);
    return true;
  }
  return false;
}

uint32_t BoardObjects::DoRead(const ObjectEntry& e,
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
      return canopen::kAbortNoData;
    }
    default:
      break;
  }
  uint32_t v = 0;
  if (!ReadNumber(e, &v)) return canopen::kAbortNoObject;
  uint8_t bytes[4];
  StoreLe32(bytes, v);
  return CopyOut(bytes, canopen::FixedSize(e.type), offset, buf, cap, copied, total);
}

uint32_t BoardObjects::WriteConfig(const ObjectEntry& e, uint32_t v) {
  BoardSettings s = pending_;
  switch (e.id) {
    case ObjectId::kNodeIdConfig:
      if (v < 1 || v > 127) return canopen::kAbortInvalidValue;
      s.node_id = static_cast<uint8_t>(v);
      break;
    case ObjectId::kBitrateConfig:
      s.bitrate_kbit = static_cast<uint16_t>(v);
      break;
    case ObjectId::kTickRateConfig:
      s.board.tick_hz = v;
      break;
    case ObjectId::kAxisCountConfig:
      if (v < 1 || v > table::kMaxAxes) return canopen::kAbortInvalidValue;
      s.board.axis_count = static_cast<uint8_t>(v);
      break;
    default: {
      if (!IsAxisConfig(e)) return canopen::kAbortReadOnly;
      AxisConfig& x = s.board.axis[e.sub - 1];
      const int32_t signed_v = static_cast<int32_t>(v);
      switch (e.index) {
        case 0x2010:
          x.name = static_cast<char>(v);
          break;
        case 0x2011:
          if (v > 1) return canopen::kAbortInvalidValue;
          x.kind = static_cast<table::AxisKind>(v);
          break;
        case 0x2013:
        case 0x2014:
          if (v > 2) return canopen::kAbortInvalidValue;
          (e.index == 0x2013 ? x.input_format : x.output_format) = static_cast<PulseFormat>(v);
          break;
        case 0x2015:
          if (signed_v < 0) return canopen::kAbortValueTooLow;
          if (signed_v > table::kMaxCorrectionSteps) return canopen::kAbortValueTooHigh;
          x.max_correction_steps = signed_v;
          break;
        case 0x2018:
          x.home_position_steps = signed_v;
          break;
        default:
          *AxisU32(x, e.index) = v;
          break;
      }
    }
  }
  // Single fields are range-checked here where they can be; the whole configuration is checked
  // at "store" (0x1010), which refuses an inconsistent set with 0x06090030.
  pending_ = s;
  return 0;
}

uint32_t BoardObjects::TableControl(uint8_t command) {
  last_command_ = command;
  const BoardConfig& board = active_.board;
  switch (static_cast<TableCommand>(command)) {
    case TableCommand::kVerify: {
      const Status s = tables_->Verify(board);
      if (!s.ok()) {
        node_->ReportEvent(kEmcyTableInvalid, canopen::kErrManufacturer,
                           static_cast<uint32_t>(s.error()));
        return canopen::kAbortInvalidValue;
      }
      return 0;
    }
    case TableCommand::kClear:
      if (!writable()) return Refuse(canopen::kAbortCannotStore);
      tables_->Clear();
      return 0;
    case TableCommand::kDeactivate:
      if (!writable()) return Refuse(canopen::kAbortCannotStore);
      if (!tables_->Deactivate().ok()) return Refuse(canopen::kAbortHardware);
      control_->RequestClearTable();
      clear_active();
      return 0;
    case TableCommand::kActivate: {
      if (!writable()) return Refuse(canopen::kAbortCannotStore);
      if (tables_->staged_state() == StagedState::kComplete) (void)tables_->Verify(board);
      if (tables_->staged_state() != StagedState::kVerified) return Refuse(canopen::kAbortNoData);
      if (!control_->engine().all_referenced() || control_->moving()) {
        return Refuse(canopen::kAbortDeviceState);
      }
      const Result<table::TableView> view = tables_->Activate();
      if (!view.ok()) return Refuse(canopen::kAbortHardware);
      PreparedTable prepared;
      if (!prepared.Prepare(*view, board).ok()) return Refuse(canopen::kAbortGeneral);
      control_->RequestTable(prepared);
      set_active(view->table_id, view->crc32);
      return 0;
    }
  }
  return canopen::kAbortInvalidValue;
}

uint32_t BoardObjects::DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
  uint32_t v = 0;
  for (uint32_t i = 0; i < size && i < 4; ++i) v |= uint32_t{data[i]} << (8 * i);
  switch (e.id) {
    case ObjectId::kUnlock:
      if (v == canopen::kUnlockSignature) {
        unlocked_ = true;
        unlocked_at_ms_ = now_ms_;
        return 0;
      }
      unlocked_ = false;  // any other value locks
      return v == 0 ? 0 : Refuse(canopen::kAbortInvalidValue);
    case ObjectId::kReferenceAxes:
      control_->RequestReference(static_cast<uint8_t>(v));
      return 0;
    case ObjectId::kCompensationEnable:
      if (v > 1) return canopen::kAbortInvalidValue;
      control_->SetBusEnable(v == 1);
      return 0;
    case ObjectId::kTableControl:
      return TableControl(static_cast<uint8_t>(v));
    case ObjectId::kStoreAll:
      if (!writable()) return Refuse(canopen::kAbortCannotStore);
      if (v != canopen::kSaveSignature) return canopen::kAbortCannotStore;
      if (!ValidateSettings(pending_).ok()) return canopen::kAbortInvalidValue;
      if (!settings_store_->Save(pending_).ok()) return Refuse(canopen::kAbortHardware);
      return 0;
    case ObjectId::kRestoreAll:
      if (!writable()) return Refuse(canopen::kAbortCannotStore);
      if (v != canopen::kLoadSignature) return canopen::kAbortCannotStore;
      if (!settings_store_->Reset().ok()) return Refuse(canopen::kAbortHardware);
      return 0;
    default:
      break;
  }
  if (e.index >= 0x2000 && e.index <= 0x201E) {
    if (!writable()) return Refuse(canopen::kAbortCannotStore);
    return WriteConfig(e, v);
  }
  return canopen::kAbortReadOnly;
}

uint32_t BoardObjects::DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) {
  if (e.id != ObjectId::kTableData) return canopen::kAbortUnsupportedAccess;
  if (!writable()) return Refuse(canopen::kAbortCannotStore);
  if (size > tables_->capacity()) return canopen::kAbortTooLong;
  if (!tables_->BeginUpload(size).ok()) return Refuse(canopen::kAbortHardware);
  return 0;
}

uint32_t BoardObjects::DoDomainWriteData(const uint8_t* data, uint32_t size) {
  const Status s = tables_->UploadData(data, size);
  if (s.ok()) return 0;
  return s.error() == Error::kImageTooLarge ? canopen::kAbortTooLong : canopen::kAbortHardware;
}

uint32_t BoardObjects::DoEndDomainWrite(bool complete) {
  const Status s = tables_->FinishUpload(complete);
  if (!complete) return 0;
  if (!s.ok())
    return s.error() == Error::kImageSizeMismatch ? canopen::kAbortTypeMismatch
                                                  : canopen::kAbortHardware;
  return 0;
}

}  // namespace volcomp::firmware
