// Native volumetric compensation for a LinuxCNC machine (no board): the firmware's compensator
// (lib/: PreparedTable lookup, clamp, CorrectionLimiter) run on the joints' commanded positions in
// the servo thread. Positions in machine units (mm), the table's axes in joint order.
//
// The configuration is made from the image itself (axis names, kinds and units per step) plus the
// limits given at load, so the table always matches; positions are converted to the table's steps
// (rounded) for the lookup, and the applied correction (Q24.8 steps) back to mm without rounding.
#pragma once

#include <cstdint>
#include <vector>

#include "volcomp/config/board_config.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/base/status.hpp"

namespace volcomp::linuxcnc {

struct NativeLimits {
  int32_t max_correction_steps = 1000;
  uint32_t rate_steps_s = 2000;
  uint32_t accel_steps_s2 = 200000;
};

class NativeCompensator {
 public:
  static constexpr uint8_t kMaxJoints = 3;

  /// Validates `image` (kept; moved in) and makes it the table, configured for a tick of
  /// `tick_hz` (the servo rate). On error nothing changes (the active table stays).
  Status Load(std::vector<uint8_t> image, uint32_t tick_hz, const NativeLimits& limits);

  /// One servo period: `pos_mm` per table axis; writes the correction to add (mm).
  void Tick(const double* pos_mm, bool enable, bool referenced, double* correction_mm);

  bool loaded() const { return loaded_; }
  uint8_t axis_count() const { return config_.axis_count; }
  char axis_name(uint8_t a) const { return config_.axis[a].name; }
  double mm_per_step(uint8_t a) const { return config_.axis[a].resolution_e9 * 1e-9; }
  bool engaged() const { return comp_.engaged(); }
  /// True when the table asks for more than the maximum correction on some axis (clamped).
  bool clamped() const { return clamped_; }
  uint32_t table_crc32() const { return comp_.table_crc32(); }
  const BoardConfig& config() const { return config_; }

 private:
  BoardConfig config_;
  Compensator comp_;
  PreparedTable table_;
  std::vector<uint8_t> image_[2];  // active image and the one a reload replaces
  int32_t last_steps_[table::kMaxAxes] = {};
  int active_ = 0;
  bool loaded_ = false;
  bool clamped_ = false;
};

}  // namespace volcomp::linuxcnc
