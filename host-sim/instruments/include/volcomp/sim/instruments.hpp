// Virtual measuring instruments. They read the actual tool point from the machine model at the
// drives' (output) positions, add their own errors, and quantise to their resolution.
//
//   LaserInterferometer (Renishaw XL-80 style), one setup at a time:
//     * linear: displacement of the tool point along the beam since the last Zero() (µm);
//     * straightness: the two components across the beam since Zero() (µm);
//     * angular: rotation of the tool side since Zero() (µrad) about x, y, z, taken as angular
//       optics and an electronic level do: from the displacement of a second point of the tool
//       side at `angular_baseline_mm` from the tool point.
//     The straightness and angular optics are aligned with the machine's nominal axes (no
//     straightness slope removed; a real straightness run fits the slope out and measures
//     squareness separately, see docs/simulator.md). The linear beam may be misaligned by
//     `misalignment_mrad` from the line of motion: it then reads cos θ times the displacement
//     along the line (the cosine error, -L·θ²/2).
//   LaserTracker: the tool point's 3-D position (mm) in the machine frame, relative to the point
//     where it was last zeroed (the tracker is registered at the machine's reference point).
//
// Errors per reading (each channel independently, Gaussian, from one seeded generator):
//   noise_*          sigma of a single sample; a reading averages `samples` of them;
//   repeatability_*  sigma of the reading-to-reading scatter that averaging does not remove
//                    (set-up, air, thermal); then rounded to `resolution_*`.
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
