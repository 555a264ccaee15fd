// ISO 230-7 error-motion analysis of one profile sampled at the same N angles in each of K
// revolutions (u[k][j], the profile minus the base circle): synchronous, asynchronous, inner and
// outer plots and the values about the PC and LSC centres and, as chosen, the MRS (minimum zone),
// MIC and MCC centres (ISO 230-7 §3.7.3–3.7.7); definitions and clauses
// in docs/metrology.md "ISO 230-7 error motion". Units those of u (µm, or µrad for tilt); angles
// in degrees.
#pragma once

#include <optional>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

/// u[k][j]: revolution k, angle j.
using Revolutions = std::vector<std::vector<double>>;

enum class CentreKind { kPc, kLsc, kMrs, kMic, kMcc };
const char* CentreName(CentreKind kind);  // "PC", "LSC", "MRS", "MIC", "MCC"

/// The centres computed besides PC and LSC (which are always).
struct CentreSelection {
  bool mrs = false;  // minimum radial separation (minimum zone), §3.7.5
  bool mic = false;  // maximum inscribed circle, §3.7.6
  bool mcc = false;  // minimum circumscribed circle, §3.7.7
};

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
  std::optional<CentreValues> mrs;  // as selected
  std::optional<CentreValues> mic;
  std::optional<CentreValues> mcc;
  double fundamental_value = 0.0;      // 2·sqrt(a² + b²) of the LSC of s (peak-to-peak of the
                                       // once-per-revolution sinusoid)
  double fundamental_angle_deg = 0.0;  // direction of the LSC offset, atan2(b, a)
  int revolutions = 0;
};

/// Needs K ≥ 1 revolutions of equal length N ≥ 4 matching angle_deg (kInvalidArgument
/// otherwise). Every centre is found from the synchronous plot (Note 1 to §3.7.7) and the values
/// of every plot are taken about it.
Expected<ErrorMotion> AnalyseErrorMotion(const std::vector<double>& angle_deg,
                                         const Revolutions& u,
                                         const CentreSelection& centres);

/// The values about one centre; a centre that was not selected falls back to LSC.
const CentreValues& ValuesAbout(const ErrorMotion& em, CentreKind kind);

/// The computed centres in the order PC, LSC, MRS, MIC, MCC.
std::vector<const CentreValues*> ComputedCentres(const ErrorMotion& em);

}  // namespace volcomp::metrology
