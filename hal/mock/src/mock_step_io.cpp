// Mock step I/O: plans -> edges -> drive models (+ timeline).
#include "volcomp/hal/mock/mock_step_io.hpp"

namespace volcomp::hal::mock {

namespace {
bool SameDrive(const AxisConfig& a, const AxisConfig& b) {
  const DriveTiming &x = a.drive, &y = b.drive;
  return a.output_format == b.output_format && x.pulse_width_ns == y.pulse_width_ns &&
         x.step_space_ns == y.step_space_ns && x.dir_setup_ns == y.dir_setup_ns &&
         x.dir_hold_ns == y.dir_hold_ns && x.max_rate_hz == y.max_rate_hz;
}
}  // namespace

MockStepIo::MockStepIo(const BoardConfig& config, Timeline* timeline)
    : config_(config), timeline_(timeline) {
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    const AxisConfig& ax = config.axis[a];
    counter_mask_[a] =
        ax.input_counter_bits >= 32 ? 0xFFFFFFFFu : ((1u << ax.input_counter_bits) - 1u);
    drives_.push_back(std::make_unique<DriveModel>(ax.output_format, ax.drive));
    line_b_[a] = ax.output_format == PulseFormat::kStepDir;
  }
  last_plans_.resize(config.axis_count);
}

Status MockStepIo::Configure(const BoardConfig& config) {
  if (config.axis_count > table::kMaxAxes || config.pulse_clock_hz == 0) {
    return Error::kConfigInvalid;
  }
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    const AxisConfig& ax = config.axis[a];
    counter_mask_[a] =
        ax.input_counter_bits >= 32 ? 0xFFFFFFFFu : ((1u << ax.input_counter_bits) - 1u);
    counters_[a] &= counter_mask_[a];
    if (a < drives_.size() && a < config_.axis_count && SameDrive(ax, config_.axis[a])) continue;
    auto drive = std::make_unique<DriveModel>(ax.output_format, ax.drive);
    if (a < drives_.size()) {
      drives_[a] = std::move(drive);
    } else {
      drives_.push_back(std::move(drive));
    }
    line_a_[a] = false;
    line_b_[a] = ax.output_format == PulseFormat::kStepDir;
    quad_phase_[a] = 0;
  }
  config_ = config;
  last_plans_.assign(config.axis_count, PulsePlan());
  ++configures_;
  return Status::Ok();
}

void MockStepIo::ReadCounters(uint32_t* counters) const {
  for (uint8_t a = 0; a < config_.axis_count; ++a) counters[a] = counters_[a];
}

void MockStepIo::Edge(uint8_t axis, uint64_t t, bool line_b, bool level) {
  (line_b ? line_b_ : line_a_)[axis] = level;
  drives_[axis]->OnEdge(t, line_b, level);
  if (timeline_ != nullptr) {
    timeline_->Record(
        {t, line_b ? EventKind::kStepLineB : EventKind::kStepLineA, axis, level ? 1 : 0});
  }
}

void MockStepIo::Apply(const PulsePlan* plans) {
  // Plan times are pulse-clock units; convert to ns.
  const uint64_t clock = config_.pulse_clock_hz;
  auto ns = [clock](uint64_t units) { return units * 1000000000ull / clock; };
  for (uint8_t a = 0; a < config_.axis_count; ++a) {
    const PulsePlan& p = plans[a];
    last_plans_[a] = p;
    const uint64_t t0 = tick_start_ns_;
    const PulseFormat f = config_.axis[a].output_format;
    if (p.dir_change && f == PulseFormat::kStepDir) Edge(a, t0 + ns(p.dir_edge), true, !p.negative);
    for (uint32_t j = 0; j < p.count; ++j) {
      const uint64_t rise = t0 + ns(p.first_rise + static_cast<uint64_t>(j) * p.period);
      if (f == PulseFormat::kQuadrature) {
        // +1 sequence (A,B) 00 -> 10 -> 11 -> 01 -> 00 is phase 0 -> 1 -> 2 -> 3 -> 0.
        const uint8_t phase = quad_phase_[a];
        const uint8_t next = static_cast<uint8_t>((phase + (p.negative ? 3 : 1)) & 3u);
        // Levels per phase: 0:(0,0) 1:(1,0) 2:(1,1) 3:(0,1).
        static const bool kA[4] = {false, true, true, false};
        static const bool kB[4] = {false, false, true, true};
        if (kA[phase] != kA[next]) Edge(a, rise, false, kA[next]);
        if (kB[phase] != kB[next]) Edge(a, rise, true, kB[next]);
        quad_phase_[a] = next;
      } else {
        const bool line_b = f == PulseFormat::kCwCcw && p.negative;
        Edge(a, rise, line_b, true);
        Edge(a, rise + ns(p.width), line_b, false);
      }
    }
  }
  ++ticks_;
}

}  // namespace volcomp::hal::mock
