// Drive input timing checker.
#include "volcomp/hal/mock/drive_model.hpp"

namespace volcomp::hal::mock {

DriveModel::DriveModel(PulseFormat format, const DriveTiming& timing)
    : format_(format), timing_(timing) {
  min_period_ns_ = (1000000000ull + timing.max_rate_hz - 1) / timing.max_rate_hz;
  level_[1] = format == PulseFormat::kStepDir;  // DIR idles high (positive); other lines low
}

void DriveModel::Violation(uint64_t t_ns, const std::string& what) {
  ++violations_;
  if (log_.size() < 16) log_.push_back("t=" + std::to_string(t_ns) + "ns: " + what);
}

void DriveModel::OnEdge(uint64_t t, bool line_b, bool level) {
  const int l = line_b ? 1 : 0;
  if (level_[l] == level) return;  // not an edge
  if (any_edge_ && t < last_edge_ns_) Violation(t, "edges out of time order");
  any_edge_ = true;
  last_edge_ns_ = t;

  if (format_ == PulseFormat::kQuadrature) {
    if (seen_[1 - l] && last_change_[1 - l] == t) Violation(t, "A and B changed together");
    const uint64_t prev = last_change_[0] > last_change_[1] ? last_change_[0] : last_change_[1];
    if ((seen_[0] || seen_[1]) && t - prev < min_period_ns_) {
      Violation(t, "quadrature edges closer than 1/max_rate");
    }
    const int from = (level_[0] ? 2 : 0) | (level_[1] ? 1 : 0);
    level_[l] = level;
    const int to = (level_[0] ? 2 : 0) | (level_[1] ? 1 : 0);
    // +1 sequence 00 -> 10 -> 11 -> 01 -> 00.
    static const int kNext[4] = {2, 0, 3, 1};
    position_ += kNext[from] == to ? 1 : -1;
    ++steps_;
    last_step_ns_ = t;
    seen_[l] = true;
    last_change_[l] = t;
    return;
  }

  const bool pulse_line = format_ == PulseFormat::kCwCcw || l == 0;
  if (pulse_line && level) {  // rising edge of a pulse line
    if (seen_[l] && t - last_fall_[l] < timing_.step_space_ns) Violation(t, "step space too short");
    if (seen_[l] && t - last_rise_[l] < min_period_ns_) Violation(t, "step rate above max_rate");
    if (format_ == PulseFormat::kStepDir) {
      if (seen_[1] && t - last_change_[1] < timing_.dir_setup_ns)
        Violation(t, "dir setup too short");
      position_ += level_[1] ? 1 : -1;
    } else {
      const int other = 1 - l;
      if (level_[other]) Violation(t, "CW and CCW high together");
      if (last_line_ == other &&
          t - last_fall_[other] <
              static_cast<uint64_t>(timing_.dir_hold_ns) + timing_.dir_setup_ns) {
        Violation(t, "CW/CCW switch faster than dir hold + setup");
      }
      last_line_ = l;
      position_ += l == 0 ? 1 : -1;
    }
    ++steps_;
    last_step_ns_ = t;
    last_rise_[l] = t;
  } else if (pulse_line) {  // falling edge
    if (t - last_rise_[l] < timing_.pulse_width_ns) Violation(t, "pulse width too short");
    last_fall_[l] = t;
  } else {  // DIR change
    if (level_[0]) Violation(t, "DIR changed while STEP high");
    if (seen_[0] && t - last_fall_[0] < timing_.dir_hold_ns) Violation(t, "dir hold too short");
    last_change_[1] = t;
  }
  seen_[l] = true;
  level_[l] = level;
}

}  // namespace volcomp::hal::mock
