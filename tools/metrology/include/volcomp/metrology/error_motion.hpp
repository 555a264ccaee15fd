// ISO 230-7 error-motion analysis of one profile sampled at the same N angles in each of K
// revolutions: u[k][j] = error motion (profile minus base circle) at angle θ_j in revolution k.
//
//   synchronous  s[j] = (1/K) Σ_k u[k][j]               (§3.5.2, §3.6.3: mean over revolutions)
//   asynchronous a[k][j] = u[k][j] − s[j]               (§3.5.5)
//   inner i[j] = min_k u[k][j], outer o[j] = max_k u[k][j]  (§3.6.7, §3.6.8)
// Values (§3.8), about a centre (a, b) computed from the synchronous plot (§3.7.7 note 1) and
// applied to the total, inner and outer plots:
//   synchronous value = max_j r_s − min_j r_s with r = p − a cos θ − b sin θ      (§3.8.3)
//   total value       = max_{k,j} r_u − min_{k,j} r_u                            (§3.8.2)
//   inner/outer value = range of r_i / r_o                                       (§3.8.7-8)
//   asynchronous value = max_j (max_k u[k][j] − min_k u[k][j]), along rays through the PC
//                        centre, independent of any centre                       (§3.8.4)
//   fundamental (axial) value = 2·|PC − LSC| of the synchronous plot             (§3.8.5)
// Units are those of u (µm, or µrad for tilt); angles in degrees.
#pragma once

#include <optional>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

/// u[k][j]: revolution k, angle j.
using Revolutions = std::vector<std::vector<double>>;

enum class CentreKind { kPc, kLsc, kMz };
const char* CentreName(CentreKind kind);  // "PC", "LSC", "MZ"

struct CentreValues {
  CentreKind kind = CentreKind::kPc;
  double a = 0.0;  // centre offset from PC along 0° (X)
  double b = 0.0;  // along 90° (Y)
  double synchronous = 0.0;
  double total = 0.0;
  double inner = 0.0;
  double outer = 0.0;
};

struct ErrorMotion {
  std::vector<double> angle_deg;
  Revolutions total;                // the input u
  std::vector<double> synchronous;  // s
  std::vector<double> inner;        // min over revolutions
  std::vector<double> outer;        // max over revolutions
  double asynchronous_value = 0.0;
  double asynchronous_angle_deg = 0.0;  // where the widest band occurs
  double lsc_mean = 0.0;                // m of the LSC fit of s
  CentreValues pc;
  CentreValues lsc;
  std::optional<CentreValues> mz;      // with the min-zone option
  double fundamental_value = 0.0;      // 2·sqrt(a² + b²) of the LSC of s (peak-to-peak of the
                                       // once-per-revolution sinusoid)
  double fundamental_angle_deg = 0.0;  // direction of the LSC offset, atan2(b, a)
  int revolutions = 0;
};

/// Needs K ≥ 1 revolutions of equal length N ≥ 4 matching angle_deg (kInvalidArgument
/// otherwise).
Expected<ErrorMotion> AnalyseErrorMotion(const std::vector<double>& angle_deg,
                                         const Revolutions& u,
                                         bool min_zone);

/// The values about one centre, for the chosen CentreKind.
const CentreValues& ValuesAbout(const ErrorMotion& em, CentreKind kind);

}  // namespace volcomp::metrology
