// The board's object dictionary values (everything outside the CiA 301 communication objects):
// identity, board configuration (pending until stored and reset), table staging and control,
// write access, operation and live diagnostics. See docs/canopen.md for the object list.
//
// Store (0x1010 = "save") writes the pending configuration together with the communication
// parameters in force (0x1015, 0x1017, read from the node); the node then restores those at its
// resets. The configuration takes effect at the next reset node.
//
// Write access: writes to tables and configuration (0x1010, 0x1011, 0x2000-0x201E, 0x2100, table
// activate/deactivate/clear) are refused with 0x08000020 unless the hardware write-enable input
// is active or the board was unlocked by writing canopen::kUnlockSignature to 0x2110 within the
// last kUnlockMs milliseconds. Table activation is refused with 0x08000022 unless every axis is
// referenced and no axis moved within kStillMs. Each refusal and each failed action is counted
// and reported with an EMCY (canopen::kEmcyRefused with the abort code, kEmcyTableInvalid with the
// error; board_protocol.hpp).
#pragma once

#include <cstdint>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen/object_values.hpp"
#include "volcomp/firmware/board_control.hpp"
#include "volcomp/firmware/settings.hpp"
#include "volcomp/firmware/table_store.hpp"

namespace volcomp::firmware {

inline constexpr uint32_t kUnlockMs = 60000;
inline constexpr uint32_t kStillMs = 100;

struct IdentityInfo {
  const char* device_name = "volcomp";
  const char* hardware_version = "host";
  const char* software_version = "0.1.0";
  uint32_t serial_number = 0;
};

class BoardObjects : public canopen::ObjectValues {
 public:
  BoardObjects(BoardControl* control,
               TableStore* tables,
               SettingsStore* settings_store,
               canopen::Node* node,
               const IdentityInfo& identity);

  /// The settings in force (from Start) and the pending copy the configuration objects edit.
  void SetSettings(const BoardSettings& active);
  const BoardSettings& pending_settings() const { return pending_; }

  /// Called every main-loop pass with the current time.
  void set_now_ms(uint32_t now_ms) { now_ms_ = now_ms; }
  bool writable() const;
  uint16_t device_state() const;
  /// 0x2102 table status word (canopen::EncodeTableStatus).
  uint32_t table_status() const;

  /// Watches the compensator's clamp and rate-limit counters (every main-loop pass, after
  /// set_now_ms): an axis is limited while its counters advanced within canopen::kLimitHoldMs
  /// (0x2134); when an axis becomes clamped, or rate limited while the axes move (a ramp at rest
  /// after activation or enabling is expected), one EMCY canopen::kEmcyCorrectionLimited names it.
  void WatchLimits();
  /// 0x2134:a+1 (canopen::CorrectionLimitBit) of axis `a`.
  uint8_t limit_flags(uint8_t a) const;
  /// 0x2123: the first rule the pending settings (with the communication parameters in force)
  /// break.
  uint32_t settings_check() const;

  uint32_t refused_actions() const { return refused_; }
  void CountFrame(bool received) { ++(received ? rx_frames_ : tx_frames_); }
  void set_active(uint32_t id, uint32_t crc) {
    active_id_ = id;
    active_crc_ = crc;
    has_active_ = true;
  }
  void clear_active() { has_active_ = false; }

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
  canopen::SdoAbort DoEndDomainWrite(canopen::SdoAbort outcome) override;
  // Table uploads are paced: the store programs flash between sub-blocks.
  uint32_t DoDomainWriteWindow() override { return tables_->upload_window(); }
  canopen::SdoAbort DoDomainWriteFlush(bool* done) override;

  bool ReadNumber(const canopen::ObjectEntry& e, uint32_t* value) const;
  // A configuration entry (bound to a BoardSettings field in od_entries.def): range check, then
  // the pending copy.
  canopen::SdoAbort WriteSetting(const canopen::ObjectEntry& e, uint32_t raw);
  canopen::SdoAbort TableControl(uint8_t command);
  // 0x1010 "save": the pending settings with the communication parameters in force.
  canopen::SdoAbort StoreSettings();
  canopen::SdoAbort Refuse(canopen::SdoAbort abort_code);
  void UpdateSettingsPending();

  BoardControl* control_;
  TableStore* tables_;
  SettingsStore* settings_store_;
  canopen::Node* node_;
  IdentityInfo identity_;
  BoardSettings active_;
  BoardSettings pending_;
  bool settings_pending_ = false;  // pending_ differs from active_
  uint32_t now_ms_ = 0;
  uint32_t unlocked_at_ms_ = 0;
  bool unlocked_ = false;
  uint8_t last_command_ = 0;
  bool has_active_ = false;
  uint32_t active_id_ = 0;
  uint32_t active_crc_ = 0;
  uint32_t refused_ = 0;
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
