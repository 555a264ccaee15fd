// Tool point from axis positions through host-sim's Machine (see the header).
#include "machine_tool_point.hpp"

#include <cstdio>
#include <cstdlib>
#include <utility>

#include "volcomp/sim/machine.hpp"

namespace volcomp::lcnc_test {

namespace {

sim::Machine MakeMachine() {
  sim::MachineOptions o;  // the built-in S500 model
  o.power_up_mm = {0.0, 0.0, 0.0};
  Expected<sim::Machine> created = sim::Machine::Create(o);
  if (!created.ok()) {  // fixed options: a failure here is a broken build
    std::fprintf(stderr, "lcnc_evaluate: %s\n", created.error().message.c_str());
    std::exit(1);
  }
  return std::move(created).value();
}

}  // namespace

model::Vec3 ToolPoint_mm(const model::Vec3& axes_mm) {
  static const sim::Machine machine = MakeMachine();
  return machine.ToolPoint_mm(axes_mm);
}

}  // namespace volcomp::lcnc_test
