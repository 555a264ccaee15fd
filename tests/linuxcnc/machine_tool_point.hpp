// The simulated machine tool behind LinuxCNC in the integration test: where the tool point is for
// the positions of its axes. The only place this test touches the host simulator's machine model,
// whose rigid-body kinematics is its own (host-sim/machine), not the formulas of tools/model that
// build the table under test; no worn-machine sources (the rigid S500 alone).
#pragma once

#include "volcomp/model/vec3.hpp"

namespace volcomp::lcnc_test {

/// Tool point (mm, machine frame) of the simulated STAN S500 (host-sim/machine) with its X, Y, Z
/// axes at `axes_mm` from the machine origin.
model::Vec3 ToolPoint_mm(const model::Vec3& axes_mm);

}  // namespace volcomp::lcnc_test
