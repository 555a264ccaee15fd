// The board's thermal model (lib/thermal thermal_model.hpp) fitted to a drift test
// (metrology/drift_test.hpp) by least squares: `volcomp build thermal`, docs/thermal.md "The PC
// tool".
//
// Per axis, every reading k of every point i after its first is one equation. The model is a
// CORRECTION: a drift of +d is fitted as a correction of −d, so with x_i = (p_i − p0)/1000 (m) and
// δT_j,ik = T_j at reading k − T_j at point i's first reading (the drift is measured from that
// reading, so the model's change since then is what it must match):
//
//   −d_ik = Σ_j offset[j]·δT_j,ik + Σ_j slope[j]·δT_j,ik·x_i          unknowns offset[j] (µm/K),
//                                                                     slope[j] (µm/(K·m))
// over the chosen channels j. The reference temperatures do not enter the fit (differences
// only); they set where the image's correction is zero: by default each channel's first reading
// in the test (the state in which the deviations were zeroed, i.e. the geometric table's state).
// p0 is the mean of the axis's points' positions; reach the largest |p − p0| over the points, or
// over the positions the image's tables cover on the axis when an image is given (the slew limit
// then holds over the whole table).
//
// Solution: the columns of the design matrix are scaled to unit length (equilibrated), the
// normal equations of the scaled system (a 2m × 2m correlation matrix, m ≤ 8) are decomposed into
// eigenvalues (cyclic Jacobi) and solved through them. Their condition number λmax/λmin is
// reported; a fit above `max_condition` (default 10⁴: two channels whose rises correlate beyond
// r ≈ 0.9998 over the test) is refused, naming the terms (and so the channels) that make up the
// eigenvector of the smallest eigenvalue: the combination the test does not determine. A channel
// whose temperature does not change is refused (nothing to fit), so is a coefficient above
// thermal::kMaxThermalCoefficient. Failures are kInputInvalid naming the axis, channel and value.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/drift_test.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::builders {

inline constexpr double kDefaultMaxCondition = 1.0e4;

struct ThermalFitOptions {
  std::vector<std::string> channels;           // channel names; empty = every channel
  std::optional<double> reference_C;           // every chosen channel's reference
  std::map<std::string, double> reference_by;  // a channel's reference (name → °C)
  double max_condition = kDefaultMaxCondition;
  /// Per axis letter, the positions an image's tables cover (mm): the reach covers them too.
  std::map<char, std::pair<double, double>> travel_mm;
};

struct ThermalFitChannel {
  std::string name;
  std::size_t number = 0;  // the board's channel (the column order in the file)
  double reference_C = 0;
  bool reference_given = false;  // from the options, else the first reading
  double min_C = 0, max_C = 0;   // seen in the test: the model's calibrated range
};

struct ThermalAxisFit {
  char name = 'X';
  double p0_mm = 0;
  double reach_mm = 0;
  bool reach_from_image = false;
  std::vector<double> offset_um_per_K;   // per chosen channel (ThermalFit::channels order)
  std::vector<double> slope_um_per_K_m;  // per chosen channel
  std::size_t samples = 0;               // readings after each point's first
  double drift_rms_um = 0;               // of the drift itself
  double residual_rms_um = 0;            // drift + fitted correction
  double residual_max_um = 0;            // largest |drift + correction|
  double explained = 0;                  // 1 − Σ residual² / Σ drift² (NaN without drift)
  double condition = 0;                  // of the equilibrated normal equations
};

struct ThermalFit {
  std::vector<ThermalFitChannel> channels;
  std::vector<ThermalAxisFit> axes;  // the record's axes, its order
  double max_condition = kDefaultMaxCondition;
};

/// The fit of every axis of `record` (see above).
Expected<ThermalFit> FitThermalModel(const metrology::DriftRecord& record,
                                     const ThermalFitOptions& options);

/// The image's model: its axis records in the order of `axes` (the image's axes, matched by name:
/// an axis of the fit that is not among them, or a rotary one, is refused), the chosen channels'
/// references and calibrated ranges (°C → cC, the range widened to whole cC), the default slew
/// limit and hold time; checked with thermal::ValidateThermalModel.
Expected<thermal::ThermalModel> ToThermalModel(const ThermalFit& fit,
                                               const table::AxisInfo* axes,
                                               std::size_t axis_count);

/// Eigenvalues (ascending) and unit eigenvectors (vectors[k] belongs to values[k]) of a
/// symmetric matrix, cyclic Jacobi; public for the tests.
struct SymmetricEigen {
  std::vector<double> values;
  std::vector<std::vector<double>> vectors;
};
SymmetricEigen EigenSymmetric(std::vector<std::vector<double>> a);

}  // namespace volcomp::builders
