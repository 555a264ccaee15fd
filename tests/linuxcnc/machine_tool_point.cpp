// Tool point from axis positions through host-sim's Machine (see the header).
#include "machine_tool_point.hpp"

#include "volcomp/sim/machine.hpp"

namespace volcomp::lcnc_test {

namespace {

sim::MachineOptions Options() {
  sim::MachineOptions o;  // the built-in S500 model
  o.power_up_mm = {0.0, 0.0, 0.0};
  return o;
}

}  // namespace

model::Vec3 ToolPoint_mm(const model::Vec3& axes_mm) {
  static const sim::Machine machine(Options());
  return machine.ToolPoint_mm(axes_mm);
}

}  // namespace volcomp::lcnc_test
