// Virtual measuring instruments: a laser interferometer (linear, straightness and angular
// optics, one setup at a time) and a laser tracker. They read the actual tool point from the
// machine at the drives' positions since their last Zero(), add their errors per channel (noise
// averaged over samples, repeatability, then rounding to the resolution; Gaussian, from one seeded
// generator) and a misaligned beam's cosine error (docs/simulator.md "Instruments").
// Lengths mm, readings µm and µrad. Thread-safety: none (the simulation's thread).
#pragma once

#include <cstdint>

#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {

struct ChannelErrors {
  double noise = 0;          // sigma of one sample
  int samples = 1;           // samples averaged per reading
  double repeatability = 0;  // sigma per reading, not reduced by averaging
  double resolution = 0;     // quantisation step (0 = none)
};

/// Applies a channel's errors to a true value.
double ApplyChannelErrors(const ChannelErrors& e, double true_value, Random& rng);

struct InterferometerOptions {
  ChannelErrors linear_um = {0.05, 16, 0.02, 0.001};   // XL-80: 1 nm resolution
  ChannelErrors angular_urad = {0.2, 16, 0.05, 0.01};  // angular optics / level
  double angular_baseline_mm = 100;  // to the second point of the tool side angular optics read
  double misalignment_mrad = 0;      // angle θ between the linear beam and the line of motion
};

struct TrackerOptions {
  ChannelErrors coordinate_um = {1.0, 4, 0.5, 0.1};  // per coordinate
};

/// One reading of the six error motions of a moving axis relative to the datum.
struct SixDofReading {
  model::Vec3 linear_um;     // x, y, z displacement minus the commanded displacement
  model::Vec3 angular_urad;  // rotation about x, y, z
};

class LaserInterferometer {
 public:
  LaserInterferometer(Machine* machine, const InterferometerOptions& options, uint64_t seed);

  /// Sets the datum with the axes at `q_mm` (commanded point `cmd_mm`).
  void Zero(const model::Vec3& q_mm, const model::Vec3& cmd_mm);
  /// Displacement along `beam` (unit vector) since the datum minus the commanded displacement
  /// along it: the positioning deviation of this approach (µm).
  double Deviation_um(const model::Vec3& q_mm, const model::Vec3& cmd_mm, const model::Vec3& beam);
  /// All six error motions since the datum (linear: deviation of each component, µm) of a run
  /// along `moving_axis`, whose component the linear beam measures (with its cosine error). The
  /// straightness and angular optics are aligned with the machine's nominal axes: no slope is
  /// removed (the straightness keeps the squareness).
  SixDofReading SixDof(const model::Vec3& q_mm, const model::Vec3& cmd_mm, int moving_axis);
  /// The same without instrument errors (for comparisons in reports and tests).
  SixDofReading SixDofTrue(const model::Vec3& q_mm, const model::Vec3& cmd_mm);

 private:
  model::Vec3 Rotation_urad(const model::Vec3& q_mm);

  Machine* machine_;
  InterferometerOptions options_;
  Random rng_;
  double cosine_ = 1;  // cos θ of the linear beam's misalignment
  model::Vec3 zero_point_mm_;
  model::Vec3 zero_cmd_mm_;
  model::Vec3 zero_rotation_urad_;
};

class LaserTracker {
 public:
  LaserTracker(Machine* machine, const TrackerOptions& options, uint64_t seed);
  /// Registers the tracker: the tool point at `q_mm` becomes the commanded point `cmd_mm`.
  void Zero(const model::Vec3& q_mm, const model::Vec3& cmd_mm);
  /// Measured tool point (mm) in the registered frame.
  model::Vec3 Measure_mm(const model::Vec3& q_mm);
  /// The same without instrument errors.
  model::Vec3 True_mm(const model::Vec3& q_mm) const;

 private:
  Machine* machine_;
  TrackerOptions options_;
  Random rng_;
  model::Vec3 offset_mm_;  // added to the actual tool point
};

}  // namespace volcomp::sim
