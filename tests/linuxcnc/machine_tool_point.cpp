// Tool point from drive counts through host-sim's Machine (see the header).
#include "machine_tool_point.hpp"

#include <map>
#include <memory>

#include "volcomp/sim/machine.hpp"

namespace volcomp::lcnc_test {

model::Vec3 ToolPoint_mm(const std::array<int64_t, 3>& drive_steps, double step_mm) {
  static std::map<double, std::unique_ptr<sim::Machine>> machines;
  std::unique_ptr<sim::Machine>& m = machines[step_mm];
  if (!m) {
    sim::MachineOptions o;  // the built-in S500 model
    o.step_mm = {step_mm, step_mm, step_mm};
    o.power_up_mm = {0.0, 0.0, 0.0};
    m = std::make_unique<sim::Machine>(o);
  }
  return m->ToolPoint_mm(m->AxisPositions_mm(drive_steps));
}

}  // namespace volcomp::lcnc_test
