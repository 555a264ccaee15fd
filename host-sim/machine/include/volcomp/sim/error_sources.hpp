// The error sources of the worn machine beyond its rigid-body geometry (worn_profile.hpp), each as
// a small piece with its formula. Lengths mm, errors µm, time seconds since the demo's time 0.
#pragma once

#include <array>
#include <cmath>

#include "volcomp/sim/worn_profile.hpp"

namespace volcomp::sim {

/// Lost motion of one axis as a play operator: the carriage stays where it is until the drive
/// has moved half the dead band past it, then follows at that distance. Offset = carriage − drive,
/// in [−L/2, +L/2]; −L/2 after positive motion, +L/2 after negative motion.
class LostMotion {
 public:
  explicit LostMotion(double lost_motion_um = 0) : half_mm_(0.5e-3 * lost_motion_um) {}
  /// The drive moved to `drive_mm` (monotonically since the last call); returns the offset (mm).
  double Follow(double drive_mm) {
    const double carriage = drive_mm_ + offset_mm_;
    drive_mm_ = drive_mm;
    offset_mm_ =
        std::fmin(std::fmax(carriage, drive_mm - half_mm_), drive_mm + half_mm_) - drive_mm;
    return offset_mm_;
  }
  /// Sets the drive position without motion (power-up), carriage centred in the dead band.
  void Reset(double drive_mm) {
    drive_mm_ = drive_mm;
    offset_mm_ = 0;
  }
  double offset_mm() const { return offset_mm_; }

 private:
  double half_mm_;
  double drive_mm_ = 0;
  double offset_mm_ = 0;
};

/// Short-period lead error of a screw: A·sin(2π·drive/P + φ), µm.
inline double ScrewError_um(double amplitude_um,
                            double period_mm,
                            double phase_rad,
                            double drive_mm) {
  return amplitude_um * std::sin(6.283185307179586 * drive_mm / period_mm + phase_rad);
}

/// First-order warm-up g(t) = G·(1 − exp(−(t_w + t)/τ)) with t_w the warm-up before time 0.
inline double WarmUp(double final_value, double tau_min, double warmup_min, double t_s) {
  return final_value * (1.0 - std::exp(-(warmup_min + t_s / 60.0) / tau_min));
}

/// Thermal growth of the worn profile at time `t_s`: how far the X carriage runs ahead at drive
/// position `x_mm` (µm) and the spindle head's growth along z (µm, negative: toward the table).
struct ThermalGrowth {
  static double XScrew_um(const WornMachineProfile& p, double x_mm, double t_s) {
    const double dT = WarmUp(p.screw_heating_K, p.screw_tau_min, p.warmup_min, t_s);
    return 1e-3 * p.screw_expansion_ppm_per_K * dT * (x_mm - p.screw_fixed_end_mm);
  }
  static double SpindleZ_um(const WornMachineProfile& p, double t_s) {
    return -WarmUp(p.spindle_growth_um, p.spindle_tau_min, p.warmup_min, t_s);
  }
};

/// Cross-axis sag: rise of the tool point relative to the workpiece (µm) at axis positions x, y
/// for a machine whose X travel is [x_min, x_max] and Y travel [y_min, y_max].
inline double CrossAxisSag_um(double sag_um,
                              double x_mm,
                              double y_mm,
                              const std::array<double, 2>& x_travel_mm,
                              const std::array<double, 2>& y_travel_mm) {
  const double ox =
      (x_mm - 0.5 * (x_travel_mm[0] + x_travel_mm[1])) / (0.5 * (x_travel_mm[1] - x_travel_mm[0]));
  const double wy = (y_mm - y_travel_mm[0]) / (y_travel_mm[1] - y_travel_mm[0]);
  return sag_um * ox * ox * wy * wy;
}

}  // namespace volcomp::sim
