// The simulated machine tool behind LinuxCNC in the integration test: where the tool point is for
// the drives' step counts. The only place this test touches the host simulator's machine model,
// whose rigid-body kinematics is its own (host-sim/machine), not the formulas of tools/model that
// build the table under test; no worn-machine sources (the rigid S500 alone).
#pragma once

#include <array>
#include <cstdint>

#include "volcomp/model/vec3.hpp"

namespace volcomp::lcnc_test {

/// Tool point (mm, machine frame) of the simulated STAN S500 (host-sim/machine) with the axes at
/// `drive_steps` x `step_mm` from the machine origin, where LinuxCNC homes and the drives start.
model::Vec3 ToolPoint_mm(const std::array<int64_t, 3>& drive_steps, double step_mm);

}  // namespace volcomp::lcnc_test
