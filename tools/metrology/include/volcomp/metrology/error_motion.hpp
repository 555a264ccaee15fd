// ISO 230-7 error-motion analysis of one profile sampled at the same N angles in each of K
// revolutions (u[k][j], the profile minus the base circle): synchronous, asynchronous, inner and
// outer plots and the values about the PC, LSC and (optionally) MZ centres; definitions and clauses
// in docs/metrology.md "ISO 230-7 error motion". Units those of u (µm, or µrad for tilt); angles
// in degrees.
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
