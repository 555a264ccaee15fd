// The board's manufacturer protocol on top of CiA 301: the values of table control (0x2101), the
// bits of device state (0x2122), the layout of the table status word (0x2102) and the EMCY codes
// the board sends, with encoders and decoders. The firmware, the PC tool, the simulator and the
// tests all use these; docs/canopen.md describes them for people.
#pragma once

#include <cstdint>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/can/can_frame.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/config/board_config.hpp"

namespace volcomp::canopen {

// ---- 0x2101 table control (U8, write) --------------------------------------------------------

enum class TableCommand : uint8_t {
  kDeactivate = 0,  // drop the active table (the correction ramps out), persistently
  kActivate = 1,    // make the verified staged table active
  kClear = 3,       // forget the staged table
  kVerify = 4,      // validate the staged table against the board
};

constexpr uint32_t Value(TableCommand c) { return static_cast<uint32_t>(c); }

// ---- 0x2127 command word (U16, rw; written by SDO or carried by RPDO1) -------------------------

/// Each bit acts on its rising edge: set in this write and clear in the last one taken (a master
/// that sends the word cyclically repeats nothing by holding a bit). The edges act in the order
/// reference, deactivate, activate, each as the SDO write it names, with the same checks; a
/// refusal is EMCY kEmcyRefused with the abort code (docs/canopen.md, "PDOs").
enum CommandWordBit : uint16_t {
  kCommandReferenceAxis1 = 0x0001,  // bits 0-5: reference request of axes 1-6 (0x2120 bit a-1)
  kCommandDeactivate = 0x0100,      // as 0x2101 = 0 (TableCommand::kDeactivate)
  kCommandActivate = 0x0200,        // as 0x2101 = 1 (TableCommand::kActivate)
};
inline constexpr uint16_t kCommandReferenceMask = 0x003F;
/// A word with other bits set, or with activate and deactivate rising together, is refused
/// (0x06090030) and not taken: the next word's edges are against the last one taken.
inline constexpr uint16_t kCommandWordBits =
    kCommandReferenceMask | kCommandDeactivate | kCommandActivate;

// ---- 0x2122 device state (U16, read) ---------------------------------------------------------

/// Bits of 0x2122.
enum DeviceStateBit : uint16_t {
  kStateReferenced = 1u << 0,       // every configured axis is referenced
  kStateEngaged = 1u << 1,          // the correction is being applied
  kStateFault = 1u << 2,            // e-stop or drive alarm
  kStateWritable = 1u << 3,         // tables and settings may be written
  kStateMoving = 1u << 4,           // an input step arrived within the last 100 ms
  kStateTableActive = 1u << 5,      // a table is active (0x2103 / 0x2104 name it)
  kStateStagedVerified = 1u << 6,   // the staged table is verified and may be activated
  kStatePassthrough = 1u << 7,      // output = input (no correction applied)
  kStateSettingsPending = 1u << 8,  // configuration edits not yet in force (store + reset)
  kStateThermalFault = 1u << 9,     // a temperature channel is in a fault, or a thermal term is
                                    // saturated (0x2151-0x2153 say which)
};
inline constexpr int kDeviceStateBitCount = 10;

/// Readable names of the bits, bit 0 first (reports).
inline constexpr const char* kDeviceStateBitNames[kDeviceStateBitCount] = {
    "referenced",   "engaged",         "fault",       "writable",         "moving",
    "table-active", "staged-verified", "passthrough", "settings-pending", "thermal-fault"};

struct DeviceState {
  bool referenced = false;
  bool engaged = false;
  bool fault = false;
  bool writable = false;
  bool moving = false;
  bool table_active = false;
  bool staged_verified = false;
  bool passthrough = false;
  bool settings_pending = false;
  bool thermal_fault = false;
};

constexpr uint16_t EncodeDeviceState(const DeviceState& s) {
  uint32_t v = 0;
  v |= s.referenced ? kStateReferenced : 0;
  v |= s.engaged ? kStateEngaged : 0;
  v |= s.fault ? kStateFault : 0;
  v |= s.writable ? kStateWritable : 0;
  v |= s.moving ? kStateMoving : 0;
  v |= s.table_active ? kStateTableActive : 0;
  v |= s.staged_verified ? kStateStagedVerified : 0;
  v |= s.passthrough ? kStatePassthrough : 0;
  v |= s.settings_pending ? kStateSettingsPending : 0;
  v |= s.thermal_fault ? kStateThermalFault : 0;
  return static_cast<uint16_t>(v);
}

constexpr DeviceState DecodeDeviceState(uint32_t v) {
  DeviceState s;
  s.referenced = (v & kStateReferenced) != 0;
  s.engaged = (v & kStateEngaged) != 0;
  s.fault = (v & kStateFault) != 0;
  s.writable = (v & kStateWritable) != 0;
  s.moving = (v & kStateMoving) != 0;
  s.table_active = (v & kStateTableActive) != 0;
  s.staged_verified = (v & kStateStagedVerified) != 0;
  s.passthrough = (v & kStatePassthrough) != 0;
  s.settings_pending = (v & kStateSettingsPending) != 0;
  s.thermal_fault = (v & kStateThermalFault) != 0;
  return s;
}

// ---- 0x2102 table status (U32, read) ---------------------------------------------------------
//
//   bit 0 busy (an upload is in progress), bits 1-7 result, bits 8-15 staged state,
//   bits 16-31 the volcomp error code of the last staging failure (error_codes.def).

/// State of the staging bank.
enum class StagedState : uint8_t {
  kEmpty = 0,      // nothing staged
  kReceiving = 1,  // an upload is in progress
  kComplete = 2,   // all bytes received, not verified yet
  kVerified = 3,   // valid image for this board: may be activated
  kFailed = 4,     // upload or verification failed (see the error code)
  kCount = 5,
};

inline constexpr const char* kStagedStateNames[] = {"empty", "receiving", "complete", "verified",
                                                    "failed"};

/// Summary of the last staging error.
enum class TableResult : uint8_t {
  kOk = 0,
  kFormat = 2,       // not a valid image
  kCrc = 3,          // CRC mismatch: the image's CRC-32, or the transfer's CRC-16
  kNotForBoard = 4,  // axes, units per step or axis count differ from the board
  kWriteError = 5,   // flash write failed
  kTooLarge = 6,     // larger than the bank
  kTransfer = 7,     // the transfer was aborted or timed out
};

constexpr TableResult TableResultOf(Error e) {
  switch (e) {
    case Error::kOk:
      return TableResult::kOk;
    case Error::kImageBadCrc:
    case Error::kTransferCrcMismatch:
      return TableResult::kCrc;
    case Error::kTransferAborted:
    case Error::kTransferTimeout:
    case Error::kTransferAbortedByClient:
      return TableResult::kTransfer;
    case Error::kConfigAxisMismatch:
    case Error::kConfigResolutionMismatch:
    case Error::kConfigTooManyAxes:
      return TableResult::kNotForBoard;
    case Error::kIoError:
      return TableResult::kWriteError;
    case Error::kImageTooLarge:
      return TableResult::kTooLarge;
    default:
      return TableResult::kFormat;
  }
}

/// The staging error of a table transfer that ended with SDO abort `a` sent by `origin`. A
/// client's abort is recorded as such whatever its code (a client's 0x05040000 is its own
/// timeout, not the board's; its code is in 0x210A).
constexpr Error TransferError(SdoAbort a, AbortOrigin origin) {
  if (origin == AbortOrigin::kClient) return Error::kTransferAbortedByClient;
  switch (a) {
    case SdoAbort::kCrc:
      return Error::kTransferCrcMismatch;
    case SdoAbort::kTimeout:
      return Error::kTransferTimeout;
    case SdoAbort::kTooLong:
    case SdoAbort::kTooShort:
      return Error::kImageSizeMismatch;  // fewer or more bytes than the client announced
    default:
      return Error::kTransferAborted;
  }
}

struct TableStatus {
  bool busy = false;
  TableResult result = TableResult::kOk;
  StagedState staged = StagedState::kEmpty;
  Error error = Error::kOk;
};

constexpr uint32_t EncodeTableStatus(const TableStatus& s) {
  return (s.busy ? 1u : 0u) | (static_cast<uint32_t>(s.result) << 1) |
         (static_cast<uint32_t>(s.staged) << 8) | (static_cast<uint32_t>(s.error) << 16);
}

constexpr TableStatus DecodeTableStatus(uint32_t v) {
  TableStatus s;
  s.busy = (v & 1u) != 0;
  s.result = static_cast<TableResult>((v >> 1) & 0x7Fu);
  s.staged = static_cast<StagedState>((v >> 8) & 0xFFu);
  s.error = static_cast<Error>(v >> 16);
  return s;
}

// ---- 0x2134 correction limited flags (U8 per axis, read)
// ------------------------------------------

/// Bits of 0x2134:a: the limit counted in 0x2135:a / 0x2136:a within the last kLimitHoldMs.
enum CorrectionLimitBit : uint8_t {
  kLimitClamped = 1u << 0,      // the table asks for more than the max correction (0x2015)
  kLimitRateLimited = 1u << 1,  // the correction moves at the max correction rate (0x2016)
};
inline constexpr uint32_t kLimitHoldMs = 100;

// ---- 0x2123 settings check (U32, read) ---------------------------------------------------------
//
//   bits 0-7 the first rule the pending settings break (volcomp::ConfigRule, 0 = none), bits 8-15
//   its axis (1-based, 0 = not an axis rule), bits 16-31 the volcomp error code (kConfigInvalid,
//   or kOk). Store (0x1010) refuses settings that break a rule with 0x06090030.

struct SettingsCheck {
  ConfigFinding finding;
  Error error = Error::kOk;
};

constexpr uint32_t EncodeSettingsCheck(const SettingsCheck& c) {
  return static_cast<uint32_t>(c.finding.rule) | (uint32_t{c.finding.axis} << 8) |
         (static_cast<uint32_t>(c.error) << 16);
}

constexpr SettingsCheck DecodeSettingsCheck(uint32_t v) {
  SettingsCheck c;
  c.finding.rule = static_cast<ConfigRule>(v & 0xFFu);
  c.finding.axis = static_cast<uint8_t>((v >> 8) & 0xFFu);
  c.error = static_cast<Error>(v >> 16);
  return c;
}

// ---- 0x2153:1 thermal status (U8, read) --------------------------------------------------------
enum ThermalStatusBit : uint8_t {
  kThermalActive = 1u << 0,     // a thermal model is in force (the active image has one)
  kThermalHolding = 1u << 1,    // a channel the model uses is in a fault: the correction is held
  kThermalFading = 1u << 2,     // the hold time ran out: the correction fades to zero
  kThermalSlewing = 1u << 3,    // the applied correction lags the model (at its slew limit)
  kThermalSaturated = 1u << 4,  // a term is saturated at the run's bounds (0x2153:4 which)
};

// ---- EMCY (COB-ID 0x080 + node-ID) -------------------------------------------------------------
//
//   bytes 0-1 the code (LE), byte 2 the error register (0x1001), bytes 3-7 manufacturer data.

inline constexpr uint16_t kEmcyErrorReset = 0x0000;         // all errors cleared
inline constexpr uint16_t kEmcyEStop = 0xFF01;              // e-stop input (until cleared)
inline constexpr uint16_t kEmcyDriveAlarm = 0xFF02;         // drive alarm input (until cleared)
inline constexpr uint16_t kEmcyConfigRefused = 0xFF03;      // settings refused: error, ConfigPart
inline constexpr uint16_t kEmcyRefused = 0xFF10;            // a request was refused: the abort code
inline constexpr uint16_t kEmcySdoTransferFailed = 0xFF11;  // SDO protocol failure: the abort code
inline constexpr uint16_t kEmcyTableInvalid = 0x6300;       // staged/stored table invalid: error
inline constexpr uint16_t kEmcyWriteFailed = 0x5530;        // flash write failed
inline constexpr uint16_t kEmcyPdoLength = 0x8210;          // CiA 301: RPDO shorter than mapped
inline constexpr uint16_t kEmcyPdoLengthExceeded = 0x8220;  // CiA 301: RPDO longer than mapped
inline constexpr uint16_t kEmcyCorrectionLimited = 0xFF20;  // the correction is clamped or rate
                                                            // limited: byte 3 clamped axes,
                                                            // byte 4 rate-limited axes (bit a-1)
/// CiA 301 "temperature": a temperature channel entered a fault (until every channel is valid
/// again): byte 3 the channels that just faulted, byte 4 every channel in a fault now, byte 5 the
/// state (thermal::ChannelState) of the lowest channel that just faulted (bit n: channel n+1).
inline constexpr uint16_t kEmcyTemperatureChannel = 0x4000;
/// A thermal term does not fit the compensation run's bounds (thermal_term.hpp) and is applied
/// saturated (until it fits): byte 3 the saturated axes (bit a-1).
inline constexpr uint16_t kEmcyThermalSaturated = 0xFF21;

/// Which part of the board refused the settings loaded at start or at a node reset
/// (kEmcyConfigRefused byte 5). The board then runs the factory defaults, except for a bit-rate
/// mismatch it can only report (kCanBitrate with kCanBitrateMismatch).
enum class ConfigPart : uint8_t {
  kNone = 0,
  kSettings = 1,    // the settings themselves (ValidateSettings)
  kTickIo = 2,      // the tick's input/output stage: step I/O hardware (pulse format, counter
                    // width, pulse clock or tick length) and step generators, or the CSP stages
  kDataPath = 3,    // ControlTick
  kTickTimer = 4,   // the tick rate
  kCanBitrate = 5,  // the CAN bit rate
  kCount = 6,
};

/// Readable names of the parts, kNone first (reports).
inline constexpr const char* kConfigPartNames[] = {"none",      "settings",   "tick I/O",
                                                   "data path", "tick timer", "CAN bit rate"};

constexpr const char* ConfigPartName(ConfigPart p) {
  return p < ConfigPart::kCount ? kConfigPartNames[static_cast<int>(p)] : "?";
}

struct Emcy {
  uint16_t code = 0;
  uint8_t error_register = 0;
  uint8_t data[5] = {};  // manufacturer bytes (frame bytes 3-7)

  /// Bytes 3-6 as LE32: the SDO abort code of kEmcyRefused and kEmcySdoTransferFailed.
  SdoAbort abort_code() const { return AbortFromCode(LoadLe32(data)); }
  /// Byte 3: the volcomp error of kEmcyTableInvalid.
  Error error() const { return static_cast<Error>(data[0]); }
  /// Bytes 3-4 as LE16: the volcomp error of kEmcyConfigRefused.
  Error config_error() const { return static_cast<Error>(LoadLe16(data)); }
  /// Byte 3 / byte 4: axes (bit a-1) whose correction is clamped / rate limited
  /// (kEmcyCorrectionLimited).
  uint8_t clamped_axes() const { return data[0]; }
  uint8_t rate_limited_axes() const { return data[1]; }
  /// Byte 5: the part that refused the settings (kEmcyConfigRefused).
  ConfigPart config_part() const { return static_cast<ConfigPart>(data[2]); }
};

/// The manufacturer bytes of kEmcyConfigRefused: `error` (LE16) and the refusing `part`.
inline void EncodeConfigRefused(Error error, ConfigPart part, uint8_t data[5]) {
  StoreLe16(data, static_cast<uint16_t>(error));
  data[2] = static_cast<uint8_t>(part);
  data[3] = data[4] = 0;
}

inline CanFrame EncodeEmcy(uint8_t node_id, const Emcy& e) {
  CanFrame f;
  f.id = kEmcyCobBase + node_id;
  f.dlc = 8;
  StoreLe16(f.data, e.code);
  f.data[2] = e.error_register;
  for (int i = 0; i < 5; ++i) f.data[3 + i] = e.data[i];
  return f;
}

/// The EMCY of `node_id` in `f`; false when `f` is not one.
inline bool DecodeEmcy(const CanFrame& f, uint8_t node_id, Emcy* out) {
  if (f.extended || f.rtr || f.dlc != 8 || f.id != kEmcyCobBase + node_id) return false;
  out->code = LoadLe16(f.data);
  out->error_register = f.data[2];
  for (int i = 0; i < 5; ++i) out->data[i] = f.data[3 + i];
  return true;
}

}  // namespace volcomp::canopen
