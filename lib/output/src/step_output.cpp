// The step/dir output stage.
#include "volcomp/output/step_output.hpp"

namespace volcomp {

Status StepOutput::Configure(const BoardConfig& config) {
  axis_count_ = 0;
  if (config.axis_count > table::kMaxAxes) return Error::kConfigInvalid;
  for (uint8_t a = 0; a < config.axis_count; ++a) {
    Axis& x = axis_[a];
    VOLCOMP_TRY(x.generator.Configure(config.axis[a], config.tick_hz, config.pulse_clock_hz));
    x.generator.Reset(0);
    x.max_backlog = 0;
  }
  overruns_ = 0;
  axis_count_ = config.axis_count;
  return Status::Ok();
}

}  // namespace volcomp
