// Simulated machines whose errors are known in closed form, for the tests of the simulator's
// machine and instruments.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "expected_value.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/sim/machine.hpp"

namespace volcomp::testing {

/// A model named "test": axes X, Y, Z over 0..100 mm whose error motions grow linearly from zero
/// at 0 to `at_100mm[axis]` at 100 mm (none by default); the model's defaults otherwise.
inline model::Model LinearErrorModel(const std::array<model::AxisErrorSample, 3>& at_100mm = {}) {
  model::Model m;
  m.name = "test";
  for (std::size_t a = 0; a < 3; ++a) {
    m.axes[a] = ValueOf(model::AxisErrorTable::Create({0, 100}, {{}, at_100mm[a]}));
  }
  return m;
}

/// The machine of `model`, with the default options otherwise.
inline sim::Machine MachineOf(model::Model model) {
  sim::MachineOptions o;
  o.model = std::move(model);
  return ValueOf(sim::Machine::Create(o));
}

}  // namespace volcomp::testing
