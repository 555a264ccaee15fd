// Tool point from drive counts through host-sim's Machine (see the header).
#include "machine_tool_point.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <utility>

#include "volcomp/sim/machine.hpp"

namespace volcomp::lcnc_test {

model::Vec3 ToolPoint_mm(const std::array<int64_t, 3>& drive_steps, double step_mm) {
  static std::map<double, std::unique_ptr<sim::Machine>> machines;
  std::unique_ptr<sim::Machine>& m = machines[step_mm];
  if (!m) {
    sim::MachineOptions o;  // the built-in S500 model
    o.step_mm = {step_mm, step_mm, step_mm};
    o.power_up_mm = {0.0, 0.0, 0.0};
    Expected<sim::Machine> created = sim::Machine::Create(o);
    if (!created.ok()) {  // fixed options: a failure here is a broken build
      std::fprintf(stderr, "lcnc_evaluate: %s\n", created.error().message.c_str());
      std::exit(1);
    }
    m = std::make_unique<sim::Machine>(std::move(created).value());
  }
  return m->ToolPoint_mm(m->AxisPositions_mm(drive_steps));
}

}  // namespace volcomp::lcnc_test
