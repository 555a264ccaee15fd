// The simulated machine tool.
#include "volcomp/sim/machine.hpp"

#include <cmath>

#include "volcomp/datasets/model_config.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::sim {

Expected<model::Model> LoadMachineModel(const std::string& spec) {
  if (spec.empty() || spec == "s500") return datasets::S500Model();
  return datasets::LoadModelConfig(spec);
}

MachineGeometry GeometryOf(const model::Model& m) {
  MachineGeometry g;
  for (size_t a = 0; a < 3; ++a) {
    const model::AxisErrorTable& t = m.axes[a];
    for (size_t i = 0; i < t.size(); ++i) {
      const model::AxisErrorSample& s = t.row(i);
      g.axes[a].push_back({t.position_mm(i),
                           {s.linear_um.x, s.linear_um.y, s.linear_um.z},
                           {s.angular_urad.x, s.angular_urad.y, s.angular_urad.z}});
    }
  }
  g.c0y_urad = m.squareness.c0y_urad;
  g.b0z_urad = m.squareness.b0z_urad;
  g.a0z_urad = m.squareness.a0z_urad;
  g.tool_offset_mm = {m.tool_offset_mm.x, m.tool_offset_mm.y, m.tool_offset_mm.z};
  g.chain = m.chain.order;
  g.carries_workpiece = m.chain.carries_workpiece;
  g.workpiece_tables_are_carriage_motion = m.chain.workpiece_errors == model::ErrorSide::kCarriage;
  g.angle_scale = m.angle_scale;
  return g;
}

namespace {

Xyz ToXyz(const model::Vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

Expected<Machine> Machine::Create(MachineOptions o) {
  if (o.model.axes[0].empty()) o.model = datasets::S500Model();
  VOLCOMP_TRY(model::ValidateModel(o.model));
  if (o.model.formulation != model::Formulation::kPhysical) {
    return Fail(Error::kInvalidArgument,
                "machine: the simulated machine is a rigid body; formulation = dissertation "
                "describes how a builder computes, not a machine");
  }
  for (size_t i = 0; i < 3; ++i) {
    if (!(o.step_mm[i] > 0))
      return Fail(Error::kInvalidArgument, "machine: step length must be > 0");
    const double lo = o.model.axes[i].min_mm(), hi = o.model.axes[i].max_mm();
    if (std::isnan(o.power_up_mm[i])) o.power_up_mm[i] = lo + 0.1 * (hi - lo);
    if (std::isnan(o.home_switch_mm[i])) o.home_switch_mm[i] = lo - 5.0;
    if (!(o.power_up_mm[i] > o.home_switch_mm[i])) {
      return Fail(Error::kInvalidArgument,
                  "machine: the axes must power up above their home switches");
    }
  }
  return Machine(std::move(o));
}

Machine::Machine(MachineOptions options)
    : options_(std::move(options)),
      kinematics_(GeometryOf(options_.model)),
      rng_(options_.wear.seed) {
  for (size_t i = 0; i < 3; ++i) {
    switch_steps_[i] =
        std::llround((options_.home_switch_mm[i] - options_.power_up_mm[i]) / options_.step_mm[i]);
    lost_motion_[i] = LostMotion(options_.wear.lost_motion ? options_.wear.lost_motion_um[i] : 0);
    lost_motion_[i].Reset(options_.power_up_mm[i]);
  }
}

double Machine::travel_min_mm(int axis) const {
  return options_.model.axes[static_cast<size_t>(axis)].min_mm();
}

double Machine::travel_max_mm(int axis) const {
  return options_.model.axes[static_cast<size_t>(axis)].max_mm();
}

void Machine::OnDriveTick(const std::array<int64_t, 3>& drive_steps, uint64_t t_ns) {
  const WornMachineProfile& w = options_.wear;
  if (!w.any()) return;
  time_s_ = static_cast<double>(t_ns) * 1e-9;
  for (size_t a = 0; a < 3; ++a) {
    if (drive_steps[a] != last_steps_[a]) {
      last_steps_[a] = drive_steps[a];
      last_step_ns_[a] = t_ns;
      moving_[a] = true;
      lost_motion_[a].Follow(options_.power_up_mm[a] +
                             static_cast<double>(drive_steps[a]) * options_.step_mm[a]);
    } else if (moving_[a] &&
               static_cast<double>(t_ns - last_step_ns_[a]) >= 1e6 * w.scatter_standstill_ms) {
      // came to rest: the carriage settles somewhere new
      moving_[a] = false;
      if (w.scatter) scatter_mm_[a] = 1e-3 * w.scatter_sigma_um[a] * rng_.Gaussian();
    }
  }
}

model::Vec3 Machine::DrivePositions_mm(const std::array<int64_t, 3>& drive_steps) const {
  model::Vec3 d;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    d[a] = options_.power_up_mm[i] + static_cast<double>(drive_steps[i]) * options_.step_mm[i];
  }
  return d;
}

model::Vec3 Machine::AxisPositions_mm(const std::array<int64_t, 3>& drive_steps) const {
  model::Vec3 q = DrivePositions_mm(drive_steps);
  const model::Vec3 d = q;
  q.x += 1e-6 * deformation_.x_screw_ppm * (d.x - deformation_.x_screw_fixed_end_mm);
  const WornMachineProfile& w = options_.wear;
  if (!w.any()) return q;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    q[a] += lost_motion_[i].offset_mm() + scatter_mm_[i];
    if (w.screw_error) {
      q[a] += 1e-3 *
              ScrewError_um(w.screw_amplitude_um[i], w.screw_period_mm, w.screw_phase_rad[i], d[a]);
    }
  }
  if (w.thermal) q.x += 1e-3 * ThermalGrowth::XScrew_um(w, d.x, time_s_);
  return q;
}

model::Vec3 Machine::ToolPoint_mm(const model::Vec3& q_mm) const {
  return PointOnTool_mm(q_mm, {0, 0, 0});
}

model::Vec3 Machine::PointOnTool_mm(const model::Vec3& q_mm, const model::Vec3& offset_mm) const {
  const Xyz p = kinematics_.ToolPoint_mm(ToXyz(q_mm), ToXyz(offset_mm));
  model::Vec3 t = model::Vec3{p[0], p[1], p[2]} - options_.model.tool_offset_mm;
  const WornMachineProfile& w = options_.wear;
  if (w.cross_axis_sag) {
    t.z += 1e-3 * CrossAxisSag_um(w.sag_um, q_mm.x, q_mm.y, {travel_min_mm(0), travel_max_mm(0)},
                                  {travel_min_mm(1), travel_max_mm(1)});
  }
  if (w.thermal) t.z += 1e-3 * ThermalGrowth::SpindleZ_um(w, time_s_);
  return t + 1e-3 * deformation_.tool_um;
}

bool Machine::HomeSwitchClosed(int axis, int64_t drive_steps) const {
  const size_t i = static_cast<size_t>(axis);
  const double offset_mm = lost_motion_[i].offset_mm();
  if (offset_mm == 0) return drive_steps <= switch_steps_[i];
  return static_cast<double>(drive_steps - switch_steps_[i]) * options_.step_mm[i] + offset_mm <= 0;
}

WornMachineProfile DefaultWornProfile(uint64_t seed) {
  WornMachineProfile p;
  p.lost_motion = p.scatter = p.screw_error = p.thermal = p.cross_axis_sag = true;
  p.seed = seed;
  return p;
}

}  // namespace volcomp::sim
