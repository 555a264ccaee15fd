// What the bus may change on the board, decided by the board's owner (BoardApp owns one policy;
// BoardObjects asks it before it acts on a write), and the requests it passes on to the tick.
//
//   write access   writes to tables and configuration are allowed while the hardware
//                  write-enable input is active or within kUnlockMs of an unlock
//                  (canopen::kUnlockSignature written to 0x2110); any other value locks.
//   activation     a verified table may become active only with every axis referenced and no
//                  axis moved within kStillMs (else canopen::SdoAbort::kDeviceState). Activate()
//                  is the one activation sequence: prepare the parsed image against the settings
//                  in force (in the hand-over slot the tick does not use), publish it to the tick,
//                  hand its thermal model (or none) to the main loop's thermal correction, record
//                  it as active (0x2103 / 0x2104). Power-up, BoardApp::ActivateImage() and 0x2101
//                  = activate all use it.
//   references     reference requests reach the tick unless the e-stop or drive alarm is active.
//
// Main loop only (the tick reads what is published through the hand-over and the atomic word).
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/canopen/node_defaults.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/firmware/board_thermal.hpp"
#include "volcomp/firmware/table_hand_over.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::firmware {

inline constexpr uint32_t kUnlockMs = 60000;
inline constexpr uint32_t kStillMs = 100;

class BoardPolicy {
 public:
  /// The owner's state the rules read and the requests go to (all BoardApp's, outliving this).
  struct Owner {
    const BoardSettings* settings = nullptr;  // in force
    const ControlTick* control_tick = nullptr;
    TableHandOver* hand_over = nullptr;
    std::atomic<uint8_t>* reference_requests = nullptr;  // bit a: reference axis a next run
    BoardThermal* thermal = nullptr;  // the thermal model in force follows the active table
  };

  explicit BoardPolicy(const Owner& owner) : owner_(owner) {}

  /// A start (power-on, reset node): locked, no table active. The inputs and the bus enable stay.
  void Restart();

  /// Every main-loop pass: the time and the slow lines.
  void set_now_ms(uint32_t now_ms) { now_ms_ = now_ms; }
  void SetLines(bool write_enable_input, bool fault) {
    write_enable_input_ = write_enable_input;
    fault_ = fault;
  }

  // ---- Write access.
  bool writable() const;
  /// A write of `value` to 0x2110: the unlock signature unlocks, anything else locks; a value
  /// other than the signature or 0 is refused (kInvalidValue) after locking.
  canopen::SdoAbort WriteUnlock(uint32_t value);

  // ---- Activation.
  /// True while any axis moved within the last kStillMs milliseconds.
  bool moving() const;
  /// kNone when a verified table may become active now, else why not (kDeviceState).
  canopen::SdoAbort MayActivate() const;
  /// The activation sequence (see above). The image bytes must stay valid and unchanged while the
  /// table is active. On error nothing changes.
  [[nodiscard]] Status Activate(const table::TableView& view);
  /// Drops the active table at the next tick (the correction ramps out; the thermal correction
  /// fades out at its slew limit).
  void Deactivate();
  bool table_active() const { return has_active_; }
  uint32_t active_table_id() const { return has_active_ ? active_id_ : 0; }
  uint32_t active_table_crc() const { return has_active_ ? active_crc_ : 0; }

  // ---- Requests to the tick.
  /// References the axes in `mask` (bit a = axis a) at the next compensation run; ignored while
  /// a fault input is active.
  void RequestReference(uint8_t mask);
  /// Compensation from the bus (AND-ed with the enable input).
  void SetBusEnable(bool on) { bus_enable_ = on; }
  bool bus_enable() const { return bus_enable_; }

  bool fault() const { return fault_; }
  bool write_enable_input() const { return write_enable_input_; }
  uint32_t now_ms() const { return now_ms_; }

 private:
  Owner owner_;
  uint32_t now_ms_ = 0;
  bool write_enable_input_ = false;
  bool fault_ = false;
  bool unlocked_ = false;
  uint32_t unlocked_at_ms_ = 0;
  bool bus_enable_ = canopen::kDefaultCompensationEnable != 0;
  bool has_active_ = false;
  uint32_t active_id_ = 0;
  uint32_t active_crc_ = 0;
};

}  // namespace volcomp::firmware
