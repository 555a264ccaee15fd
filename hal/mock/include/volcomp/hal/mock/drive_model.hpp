// A stepper/servo drive's pulse input, as a checker: counts the steps it receives and flags every
// edge that breaks its timing requirements (times in ns, from DriveTiming). Written from the
// drive's side (datasheet rules on line levels), independently of the step generator it checks;
// the rules per output format: docs/control-path.md, "Step generator".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/config/board_config.hpp"

namespace volcomp::hal::mock {

class DriveModel {
 public:
  DriveModel(PulseFormat format, const DriveTiming& timing);

  /// Line A (STEP / CW / A) or B (DIR / CCW / B) changed to `level` at `t_ns` (non-decreasing).
  void OnEdge(uint64_t t_ns, bool line_b, bool level);

  int64_t position() const { return position_; }
  uint64_t steps() const { return steps_; }
  uint64_t violations() const { return violations_; }
  /// The first few violations, described (for test messages).
  const std::vector<std::string>& violation_log() const { return log_; }
  /// Time of the last step edge counted (0 if none).
  uint64_t last_step_ns() const { return last_step_ns_; }

 private:
  void Violation(uint64_t t_ns, const std::string& what);

  PulseFormat format_;
  DriveTiming timing_;
  uint64_t min_period_ns_;
  bool level_[2] = {false, true};  // DIR starts high (positive)
  bool seen_[2] = {false, false};
  uint64_t last_rise_[2] = {0, 0};
  uint64_t last_fall_[2] = {0, 0};
  uint64_t last_change_[2] = {0, 0};
  int last_line_ = -1;  // CW/CCW: which line pulsed last
  int64_t position_ = 0;
  uint64_t steps_ = 0;
  uint64_t last_step_ns_ = 0;
  uint64_t last_edge_ns_ = 0;
  bool any_edge_ = false;
  uint64_t violations_ = 0;
  std::vector<std::string> log_;
};

}  // namespace volcomp::hal::mock
