// CAN gateway for CiA 402 cyclic synchronous position (CSP) between the controller's bus and the
// drives' bus: forwards every frame both ways bit for bit, except that the mapped target positions
// (0x607A) get the axis's correction added and the mapped actual positions (0x6064) get the
// correction in force for that sample subtracted (FeedbackMode); frames of the board's own node
// are not forwarded. Units: drive increments = board steps, INTEGER32 wrapping. Per frame: at most
// kMaxPdoMaps entries scanned, no division, no allocation. Threading: Configure/FromController/
// FromDrive from one context; the tick's InputCounter()/SetCorrection() may preempt them (one
// atomic word per axis). Rules: docs/linux-board.md, "How the gateway works".
#pragma once

#include <atomic>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/can/can_frame.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::gateway {

inline constexpr uint8_t kMaxPdoMaps = 16;
inline constexpr uint16_t kDefaultSyncCobId = 0x080;  // CiA 301 0x1005 default

/// What a mapped 32-bit field holds.
enum class PdoField : uint8_t {
  kTargetPosition = 0,  // 0x607A, in a frame from the controller (the drive's RPDO)
  kActualPosition = 1,  // 0x6064, in a frame from a drive (the drive's TPDO)
};

/// Which correction is removed from an actual position: the one added to the last target
/// forwarded before the latest SYNC (the target the drive took over at that SYNC; needs SYNC), or
/// the one added to the last target forwarded (drives without SYNC).
enum class FeedbackMode : uint8_t { kAtSync = 0, kLatest = 1 };

/// One mapped field: the INTEGER32 (little-endian) at data[offset .. offset + 3] of the PDO with
/// this 11-bit COB-ID belongs to board axis `axis`.
struct PdoMap {
  uint16_t cob_id = 0;
  PdoField field = PdoField::kTargetPosition;
  uint8_t offset = 0;  // 0..4
  uint8_t axis = 0;    // 0 .. axis_count - 1
};

struct GatewayConfig {
  uint8_t map_count = 0;
  PdoMap map[kMaxPdoMaps];
  uint16_t sync_cob_id = kDefaultSyncCobId;
  uint8_t own_node_id = 0;  // the board's node-ID, 1..127; 0 = the board has no node on the bus
  FeedbackMode feedback = FeedbackMode::kAtSync;
  bool invert[table::kMaxAxes] = {};  // the drive's positive direction is the machine's negative
};

/// Checks `config` for a board with `axis_count` axes: mapped COB-IDs 0x001..0x7FF, neither the
/// SYNC COB-ID nor one of the board's own (0x080/0x580/0x600/0x700 + node-ID, which the SYNC must
/// not be either); offset <= 4; axis in range; at most one target and one actual field per axis;
/// no overlapping fields in one PDO. kConfigInvalid otherwise.
Status ValidateGatewayConfig(const GatewayConfig& config, uint8_t axis_count);

/// What to do with a frame after the gateway looked at it.
enum class Route : uint8_t {
  kForward,  // send *out on the other bus
  kLocal,    // for the board's own node only (do not forward)
  kDrop,     // do not forward (conflicts with the board's own COB-IDs)
};

struct GatewayCounters {
  uint32_t from_controller = 0;    // frames received on the CNC side
  uint32_t from_drives = 0;        // frames received on the drive side
  uint32_t targets_corrected = 0;  // mapped target fields rewritten
  uint32_t actuals_corrected = 0;  // mapped actual fields rewritten
  uint32_t short_pdos = 0;         // mapped PDO too short for its field: forwarded untouched
  uint32_t local = 0;              // frames for the board's own SDO server
  uint32_t conflicts = 0;          // drive-side frames with the board's own COB-IDs (dropped)
  uint32_t syncs = 0;              // SYNC frames from the controller
};

class CspGateway {
 public:
  /// Validates and applies `config`; clears targets, corrections and counters.
  Status Configure(const GatewayConfig& config, uint8_t axis_count);

  /// A frame from the controller's bus. *out is the frame to forward (equal to `in` unless a
  /// target field was corrected). Records the commanded positions.
  Route FromController(const CanFrame& in, CanFrame* out);
  /// A frame from the drives' bus. *out is the frame to forward.
  Route FromDrive(const CanFrame& in, CanFrame* out);

  /// The correction of `axis` in machine steps (the control tick's output), used for every
  /// target forwarded from now on.
  void SetCorrection(uint8_t axis, int32_t machine_steps);

  /// The commanded position of `axis` in machine direction, relative to the first target seen
  /// (0 before it), as a wrapping 32-bit counter: what the control tick reads as its input.
  uint32_t InputCounter(uint8_t axis) const {
    return counter_[axis].load(std::memory_order_relaxed);
  }
  /// True once a target for `axis` was forwarded.
  bool has_target(uint8_t axis) const { return has_target_[axis]; }
  /// The last target received for `axis` (drive increments, uncorrected).
  int32_t last_target(uint8_t axis) const { return last_target_[axis]; }
  /// Drive increments added to the last target forwarded for `axis`.
  int32_t sent_correction(uint8_t axis) const { return sent_[axis]; }
  /// Drive increments currently removed from the actual position of `axis`.
  int32_t feedback_correction(uint8_t axis) const {
    return config_.feedback == FeedbackMode::kAtSync ? at_sync_[axis] : sent_[axis];
  }
  const GatewayCounters& counters() const { return counters_; }
  const GatewayConfig& config() const { return config_; }

 private:
  bool IsOwnTxCobId(uint32_t id) const;

  GatewayConfig config_;
  uint8_t axis_count_ = 0;
  GatewayCounters counters_;
  std::atomic<int32_t> correction_[table::kMaxAxes] = {};  // drive increments, next target
  int32_t sent_[table::kMaxAxes] = {};                     // added to the last forwarded target
  int32_t at_sync_[table::kMaxAxes] = {};                  // sent_ at the last SYNC
  int32_t last_target_[table::kMaxAxes] = {};
  uint32_t base_[table::kMaxAxes] = {};  // machine-direction value of the first target
  std::atomic<uint32_t> counter_[table::kMaxAxes] = {};
  bool has_target_[table::kMaxAxes] = {};
};

}  // namespace volcomp::gateway
