// The board's object dictionary values (everything the node does not answer itself; the object
// list: docs/canopen.md), bound from the od_entries.def rows: a configuration object
// (VOLCOMP_OD_SETTING) reads and writes its field of the pending settings, a produced value
// (VOLCOMP_OD_VALUE / VOLCOMP_OD_AXIS_ARRAY) reads the accessor below that its row names, any
// other number is its row's default; per-axis values of axes not configured read 0.
//
// The pending settings take effect at the next reset node, after a store (0x1010 "save", with the
// communication parameters in force); BoardApp owns the settings in force, this class reads them.
// What the bus may change is BoardPolicy's decision: refusals are 0x08000020 (not writable) or
// 0x08000022 (activation not allowed now), each counted (0x2140:9) and reported by EMCY
// (canopen::kEmcyRefused; a failed verification canopen::kEmcyTableInvalid). Main loop only.
#pragma once

#include <cstdint>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/identity.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/board_control.hpp"
#include "volcomp/firmware/board_policy.hpp"
#include "volcomp/firmware/board_thermal.hpp"
#include "volcomp/firmware/settings_store.hpp"
#include "volcomp/firmware/table_store.hpp"

namespace volcomp::firmware {

/// The node's communication parameters in `s` (0x1015, 0x1017, the PDOs): what a start puts in
/// force and what a reset communication restores.
inline canopen::CommunicationParameters CommunicationOf(const BoardSettings& s) {
  canopen::CommunicationParameters c;
  c.heartbeat_ms = s.heartbeat_ms;
  c.emcy_inhibit_100us = s.emcy_inhibit_100us;
  for (uint8_t n = 0; n < kTpdoCount; ++n) c.tpdo[n] = s.tpdo[n];
  for (uint8_t n = 0; n < kRpdoCount; ++n) c.rpdo[n] = s.rpdo[n];
  return c;
}

// 0x1008-0x100A (canopen/identity.hpp): a port names its hardware with canopen::HardwareVersion.
struct IdentityInfo {
  const char* device_name = canopen::kDeviceNameText;
  const char* hardware_version = canopen::HardwareVersion(canopen::Hardware::kBoard);
  const char* software_version = canopen::kSoftwareVersionText;
  uint32_t serial_number = 0;
};

class BoardObjects : public canopen::ObjectValues {
 public:
  /// The owner's parts the values come from and the actions go to (all outliving this).
  struct Parts {
    const BoardControl* control = nullptr;
    BoardPolicy* policy = nullptr;
    const BoardSettings* settings_in_force = nullptr;
    const ControlTick* control_tick = nullptr;
    TableStore* tables = nullptr;
    SettingsStore* settings_store = nullptr;
    canopen::Node* node = nullptr;
    OutputStage output_stage = OutputStage::kAny;  // the settings rules (0x2123, 0x1010)
    BoardThermal* thermal = nullptr;               // channels 0x2150-0x2152, 0x2153-0x2155
  };

  BoardObjects(const Parts& parts, const IdentityInfo& identity);

  /// The configuration objects' pending copy back to the settings in force (at a start).
  void ResetPendingSettings();
  const BoardSettings& pending_settings() const { return pending_; }

  /// Watches the compensator's clamp and rate-limit counters (every main-loop pass): an axis is
  /// limited while its counters advanced within canopen::kLimitHoldMs (0x2134); when an axis
  /// becomes clamped, or rate limited while the axes move (a ramp at rest after activation or
  /// enabling is expected), one EMCY canopen::kEmcyCorrectionLimited names it.
  void WatchLimits(uint32_t now_ms);
  void CountFrame(bool received) { ++(received ? rx_frames_ : tx_frames_); }

  // ---- Values, one accessor per VOLCOMP_OD_VALUE / VOLCOMP_OD_AXIS_ARRAY row (the row's name).
  uint32_t serial_number() const { return identity_.serial_number; }
  uint8_t table_control() const { return last_command_; }  // the last command written
  /// 0x2102 table status word (canopen::EncodeTableStatus).
  uint32_t table_status() const;
  uint32_t active_table_id() const { return parts_.policy->active_table_id(); }
  uint32_t active_table_crc() const { return parts_.policy->active_table_crc(); }
  uint32_t staged_table_crc() const { return parts_.tables->staged_crc32(); }
  uint32_t staged_bytes() const { return parts_.tables->staged_bytes(); }
  uint32_t staged_table_id() const { return parts_.tables->staged_table_id(); }
  uint32_t table_bank_size() const { return parts_.tables->capacity(); }
  /// 0x210A: the SDO abort code that ended the last table transfer (the client's or the
  /// board's), while 0x2102 reports that transfer's failure; 0 otherwise.
  uint32_t transfer_abort_code() const;
  uint8_t write_access() const { return parts_.policy->writable() ? 1 : 0; }
  uint8_t compensation_enable() const { return parts_.policy->bus_enable() ? 1 : 0; }
  /// 0x2122 (canopen::EncodeDeviceState).
  uint16_t device_state() const;
  /// 0x2123: the first rule the pending settings (with the communication parameters in force)
  /// break (canopen::EncodeSettingsCheck).
  uint32_t settings_check() const;
  int32_t commanded_position(uint8_t a) const { return parts_.control_tick->commanded(a); }
  int32_t applied_correction(uint8_t a) const {
    return parts_.control_tick->compensator().applied_q8(a);
  }
  int32_t output_position(uint8_t a) const {
    return parts_.control->output_status().position_steps[a];
  }
  uint32_t max_backlog(uint8_t a) const {
    return parts_.control->output_status().max_backlog_steps[a];
  }
  /// 0x2125 / 0x2126: the axes clamped / rate limited now (bit a-1 for axis a: 0x2134's flags
  /// gathered, for a TPDO).
  uint8_t clamped_axes() const { return clamped_mask_; }
  uint8_t rate_limited_axes() const { return limited_mask_; }
  /// 0x2138: the applied correction (0x2131, q8) rounded to whole steps (half away from zero),
  /// saturated at +-32767: the TPDOs' 16-bit form of it.
  int16_t correction_steps(uint8_t a) const;
  /// 0x2134:a+1 (canopen::CorrectionLimitBit) of axis `a`.
  uint8_t correction_limited(uint8_t a) const;
  uint32_t clamped_refreshes(uint8_t a) const {
    return parts_.control_tick->compensator().clamped_refreshes(a);
  }
  uint32_t rate_limited_refreshes(uint8_t a) const {
    return parts_.control_tick->compensator().rate_limited_refreshes(a);
  }
  /// The table's coordinate: commanded + reference offset.
  int32_t machine_position(uint8_t a) const { return parts_.control_tick->machine_position(a); }
  uint32_t can_rx_frames() const { return rx_frames_; }
  uint32_t can_tx_frames() const { return tx_frames_; }
  uint32_t malformed_frames() const { return parts_.node->malformed(); }
  uint32_t sdo_aborts() const { return parts_.node->sdo().aborts(); }
  uint32_t emcy_sent() const { return parts_.node->emcy_sent(); }
  uint32_t ticks() const { return static_cast<uint32_t>(parts_.control_tick->ticks()); }
  uint32_t output_overruns() const { return parts_.control->output_status().overruns; }
  uint32_t max_tick_cost() const { return parts_.control->max_tick_cost_ns(); }
  uint32_t refused_actions() const { return refused_; }
  /// 0x2127: the last command word taken (canopen::CommandWordBit).
  uint16_t command_word() const { return command_word_; }
  uint32_t emcy_suppressed() const { return parts_.node->emcy_suppressed(); }
  /// Axes whose per-axis values are live (the others read 0).
  uint8_t axis_count() const { return parts_.control_tick->axis_count(); }

  // ---- Thermal compensation (docs/thermal.md), per channel ch = 0..7 or per axis.
  /// 0x2150: the accepted temperature, 0.01 C (held through a fault; 0 before the first).
  int16_t temperature(uint8_t ch) const { return parts_.thermal->channels().value_cC(ch); }
  /// 0x2151: thermal::ChannelState.
  uint8_t temperature_state(uint8_t ch) const {
    return static_cast<uint8_t>(parts_.thermal->channels().state(ch));
  }
  /// 0x2152: fault onsets since the start.
  uint16_t temperature_faults(uint8_t ch) const {
    return parts_.thermal->channels().fault_count(ch);
  }
  /// 0x2153:1 (canopen::ThermalStatusBit): a model in force, holding, fading, slewing, saturated.
  uint8_t thermal_status() const;
  /// 0x2153:2: every configured channel in a fault (bit n: channel n+1).
  uint8_t thermal_fault_channels() const { return parts_.thermal->channel_fault_mask(); }
  /// 0x2153:3: channels the model uses that are outside its calibrated range (taken at its edge).
  uint8_t thermal_outside_channels() const {
    return parts_.thermal->correction().status().outside_mask;
  }
  /// 0x2153:4: axes whose thermal terms are saturated (bit a-1).
  uint8_t thermal_saturated_axes() const { return parts_.thermal->saturated_axes(); }
  /// 0x2154 / 0x2155: the applied thermal offset (nm, at the model's p0) and slope (nm per m of
  /// travel), rounded.
  int32_t thermal_offset(uint8_t a) const;
  int32_t thermal_slope(uint8_t a) const;

 private:
  canopen::SdoAbort DoRead(const canopen::ObjectEntry& e,
                           uint32_t offset,
                           uint8_t* buf,
                           uint32_t cap,
                           uint32_t* copied,
                           uint32_t* total) override;
  canopen::SdoAbort DoWrite(const canopen::ObjectEntry& e,
                            const uint8_t* data,
                            uint32_t size) override;
  canopen::SdoAbort DoBeginDomainWrite(const canopen::ObjectEntry& e, uint32_t size) override;
  canopen::SdoAbort DoDomainWriteData(const uint8_t* data, uint32_t size) override;
  canopen::SdoAbort DoEndDomainWrite(canopen::SdoAbort outcome,
                                     canopen::AbortOrigin origin) override;
  uint32_t DoDomainWriteWindow() override { return parts_.tables->upload_window(); }
  canopen::SdoAbort DoDomainWriteFlush(bool* done) override;

  bool ReadNumber(const canopen::ObjectEntry& e, uint32_t* value) const;
  // A configuration entry (bound to a BoardSettings field in od_entries.def): range check, then
  // the pending copy.
  canopen::SdoAbort WriteSetting(const canopen::ObjectEntry& e, uint32_t raw);
  canopen::SdoAbort TableControl(uint8_t command);
  // 0x2150: a reading of a channel whose source is the CAN object.
  canopen::SdoAbort WriteTemperature(uint8_t ch, uint32_t raw);
  // 0x2127: the rising edges of `word` against the last word taken.
  canopen::SdoAbort CommandWord(uint16_t word);
  // 0x1010 "save": the pending settings with the communication parameters in force.
  canopen::SdoAbort StoreSettings();
  canopen::SdoAbort Refuse(canopen::SdoAbort abort_code);
  // `s` with the node's communication parameters in force (what a store saves, what 0x2124 says).
  BoardSettings WithCommunication(BoardSettings s) const;
  void UpdateSettingsPending();

  Parts parts_;
  IdentityInfo identity_;
  BoardSettings pending_;
  bool settings_pending_ = false;  // pending_ differs from the settings in force
  uint8_t last_command_ = 0;
  uint16_t command_word_ = 0;
  uint32_t refused_ = 0;
  canopen::SdoAbort transfer_abort_ = canopen::SdoAbort::kNone;  // of the last broken transfer
  uint32_t now_ms_ = 0;                                          // at the last WatchLimits()
  uint32_t seen_clamped_[table::kMaxAxes] = {};  // counters at the last WatchLimits()
  uint32_t seen_limited_[table::kMaxAxes] = {};
  uint32_t clamped_at_ms_[table::kMaxAxes] = {};  // when they last advanced
  uint32_t limited_at_ms_[table::kMaxAxes] = {};
  uint8_t clamped_mask_ = 0;  // axes limited now (bit a)
  uint8_t limited_mask_ = 0;
  uint8_t reported_clamped_ = 0;  // axes whose clamping / rate limiting has been reported
  uint8_t reported_limited_ = 0;
  uint32_t rx_frames_ = 0;
  uint32_t tx_frames_ = 0;
};

}  // namespace volcomp::firmware
