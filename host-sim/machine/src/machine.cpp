// The simulated machine tool.
#include "volcomp/sim/machine.hpp"

#include <cmath>
#include <stdexcept>

#include "volcomp/model/io.hpp"
#include "volcomp/model/s500.hpp"

namespace volcomp::sim {

model::Model LoadMachineModel(const std::string& spec) {
  if (spec.empty() || spec == "s500") return model::S500Model();
  return model::LoadModelConfig(spec);
}

Machine::Machine(MachineOptions options) : options_(std::move(options)) {
  if (options_.model.axes[0].empty()) options_.model = model::S500Model();
  model::ValidateModel(options_.model);
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    if (!(options_.step_mm[i] > 0)) throw std::invalid_argument("machine: step length must be > 0");
    const double lo = travel_min_mm(a), hi = travel_max_mm(a);
    if (std::isnan(options_.power_up_mm[i])) options_.power_up_mm[i] = lo + 0.1 * (hi - lo);
    if (std::isnan(options_.home_switch_mm[i])) options_.home_switch_mm[i] = lo - 5.0;
    if (!(options_.power_up_mm[i] > options_.home_switch_mm[i])) {
      throw std::invalid_argument("machine: the axes must power up above their home switches");
    }
    switch_steps_[i] =
        std::llround((options_.home_switch_mm[i] - options_.power_up_mm[i]) / options_.step_mm[i]);
  }
}

double Machine::travel_min_mm(int axis) const {
  return options_.model.axes[static_cast<size_t>(axis)].min_mm();
}

double Machine::travel_max_mm(int axis) const {
  return options_.model.axes[static_cast<size_t>(axis)].max_mm();
}

model::Vec3 Machine::AxisPositions_mm(const std::array<int64_t, 3>& drive_steps) const {
  model::Vec3 q;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    q[a] = options_.power_up_mm[i] + static_cast<double>(drive_steps[i]) * options_.step_mm[i];
  }
  return q;
}

model::Vec3 Machine::ToolPoint_mm(const model::Vec3& q_mm) const {
  return q_mm + 1e-3 * model::ToolPointError_um(options_.model, q_mm);
}

model::Vec3 Machine::PointOnTool_mm(const model::Vec3& q_mm, const model::Vec3& offset_mm) {
  const std::array<double, 3> key = {offset_mm.x, offset_mm.y, offset_mm.z};
  auto it = offset_models_.find(key);
  if (it == offset_models_.end()) {
    model::Model m = options_.model;
    m.tool_offset_mm = m.tool_offset_mm + offset_mm;
    it = offset_models_.emplace(key, std::move(m)).first;
  }
  // The nominal position of that point is q + tool offset + offset; the model reports the error
  // relative to q + its tool offset, so add the offset back.
  return q_mm + offset_mm + 1e-3 * model::ToolPointError_um(it->second, q_mm);
}

bool Machine::HomeSwitchClosed(int axis, int64_t drive_steps) const {
  return drive_steps <= switch_steps_[static_cast<size_t>(axis)];
}

}  // namespace volcomp::sim
