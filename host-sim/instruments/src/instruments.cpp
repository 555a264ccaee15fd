// Virtual laser interferometer and laser tracker.
#include "volcomp/sim/instruments.hpp"

#include <cmath>

namespace volcomp::sim {

double ApplyChannelErrors(const ChannelErrors& e, double true_value, Random& rng) {
  double v = true_value;
  if (e.noise > 0) {
    const int n = e.samples > 0 ? e.samples : 1;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += rng.Gaussian();
    v += e.noise * sum / n;
  }
  if (e.repeatability > 0) v += e.repeatability * rng.Gaussian();
  if (e.resolution > 0) v = e.resolution * std::round(v / e.resolution);
  return v;
}

LaserInterferometer::LaserInterferometer(Machine* machine,
                                         const InterferometerOptions& options,
                                         uint64_t seed)
    : machine_(machine),
      options_(options),
      rng_(seed),
      cosine_(std::cos(1e-3 * options.misalignment_mrad)) {}

model::Vec3 LaserInterferometer::Rotation_urad(const model::Vec3& q_mm) {
  // omega x (d e_y) = d(-wz, 0, wx); omega x (d e_z) = d(wy, -wx, 0); omega x (d e_x) = d(0, wz,
  // -wy)
  const double d = options_.angular_baseline_mm;
  const model::Vec3 p0 = machine_->PointOnTool_mm(q_mm, {0, 0, 0});
  const model::Vec3 px = machine_->PointOnTool_mm(q_mm, {d, 0, 0}) - p0;
  const model::Vec3 py = machine_->PointOnTool_mm(q_mm, {0, d, 0}) - p0;
  const model::Vec3 pz = machine_->PointOnTool_mm(q_mm, {0, 0, d}) - p0;
  const double wx = py.z / d;
  const double wy = pz.x / d;
  const double wz = px.y / d;
  return {1e6 * wx, 1e6 * wy, 1e6 * wz};
}

void LaserInterferometer::Zero(const model::Vec3& q_mm, const model::Vec3& cmd_mm) {
  zero_point_mm_ = machine_->ToolPoint_mm(q_mm);
  zero_cmd_mm_ = cmd_mm;
  zero_rotation_urad_ = Rotation_urad(q_mm);
}

double LaserInterferometer::Deviation_um(const model::Vec3& q_mm,
                                         const model::Vec3& cmd_mm,
                                         const model::Vec3& beam) {
  const model::Vec3 moved = machine_->ToolPoint_mm(q_mm) - zero_point_mm_;
  const model::Vec3 commanded = cmd_mm - zero_cmd_mm_;
  const double true_um = 1e3 * (cosine_ * model::Dot(moved, beam) - model::Dot(commanded, beam));
  return ApplyChannelErrors(options_.linear_um, true_um, rng_);
}

SixDofReading LaserInterferometer::SixDofTrue(const model::Vec3& q_mm, const model::Vec3& cmd_mm) {
  SixDofReading r;
  const model::Vec3 moved = machine_->ToolPoint_mm(q_mm) - zero_point_mm_;
  r.linear_um = 1e3 * (moved - (cmd_mm - zero_cmd_mm_));
  r.angular_urad = Rotation_urad(q_mm) - zero_rotation_urad_;
  return r;
}

SixDofReading LaserInterferometer::SixDof(const model::Vec3& q_mm,
                                          const model::Vec3& cmd_mm,
                                          int moving_axis) {
  SixDofReading r = SixDofTrue(q_mm, cmd_mm);
  if (cosine_ != 1) {
    const model::Vec3 moved = machine_->ToolPoint_mm(q_mm) - zero_point_mm_;
    r.linear_um[moving_axis] += 1e3 * (cosine_ - 1) * moved[moving_axis];
  }
  for (int i = 0; i < 3; ++i) {
    r.linear_um[i] = ApplyChannelErrors(options_.linear_um, r.linear_um[i], rng_);
  }
  for (int i = 0; i < 3; ++i) {
    r.angular_urad[i] = ApplyChannelErrors(options_.angular_urad, r.angular_urad[i], rng_);
  }
  return r;
}

LaserTracker::LaserTracker(Machine* machine, const TrackerOptions& options, uint64_t seed)
    : machine_(machine), options_(options), rng_(seed) {}

void LaserTracker::Zero(const model::Vec3& q_mm, const model::Vec3& cmd_mm) {
  offset_mm_ = cmd_mm - machine_->ToolPoint_mm(q_mm);
}

model::Vec3 LaserTracker::True_mm(const model::Vec3& q_mm) const {
  return machine_->ToolPoint_mm(q_mm) + offset_mm_;
}

model::Vec3 LaserTracker::Measure_mm(const model::Vec3& q_mm) {
  const model::Vec3 t = True_mm(q_mm);
  model::Vec3 m;
  for (int i = 0; i < 3; ++i) {
    m[i] = 1e-3 * ApplyChannelErrors(options_.coordinate_um, 1e3 * t[i], rng_);
  }
  return m;
}

}  // namespace volcomp::sim
