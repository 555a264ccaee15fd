// Evaluation of a positioning test per GOST 27843-88 (coverage factor k = 3) or ISO 230-2:2014
// (k = 2): per target and direction the mean, standard deviation, reversal and repeatability, and
// the overall parameters (A, R, B, E, M ...) with the position and direction of every extreme.
// Formulas and clauses: docs/metrology.md. Units: µm (linear axis) or arc-seconds (rotary axis).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/direction.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/positioning_uncertainty.hpp"

namespace volcomp::metrology {

enum class Standard { kGost27843, kIso230_2 };
/// GOST 27843 formula (5) (sample standard deviation) or formula (6) (range × a_n, n = 5..10).
/// ISO 230-2 always uses the formula.
enum class SigmaMethod { kFormula, kRange };

const char* StandardName(Standard s);  // "GOST 27843-88" or "ISO 230-2:2014"

struct EvaluationOptions {
  Standard standard = Standard::kGost27843;
  SigmaMethod sigma = SigmaMethod::kFormula;
};

/// Coverage factor of the standard: 3 (GOST 27843) or 2 (ISO 230-2:2014).
double CoverageFactor(Standard s);

struct DirectionStats {
  int n = 0;
  double mean = 0.0;           // X̄_j
  double s = 0.0;              // S_j (by the chosen method)
  double range = 0.0;          // W_j (formula (4))
  double upper = 0.0;          // X̄_j + k·S_j
  double lower = 0.0;          // X̄_j − k·S_j
  double repeatability = 0.0;  // R_j = 2k·S_j
};

struct PositionStats {
  std::size_t index = 0;  // 0-based; position number j = index + 1
  double target = 0.0;    // mm or degrees
  std::optional<DirectionStats> up;
  std::optional<DirectionStats> down;
  // Bidirectional, present when both directions are:
  std::optional<double> reversal;                     // B_j = X̄_j↑ − X̄_j↓
  std::optional<double> mean_bidirectional;           // x̄_j = (X̄_j↑ + X̄_j↓)/2
  std::optional<double> repeatability_bidirectional;  // R_j (GOST (8), ISO R_j)
};

/// One extreme value and where it occurs.
struct Extreme {
  double value = 0.0;
  std::size_t position = 0;            // index into PositioningResult::positions
  std::optional<Direction> direction;  // for values of one direction
};

/// A range parameter max − min with both locations.
struct Span {
  double value = 0.0;
  Extreme max;
  Extreme min;
};

struct PositioningResult {
  Standard standard = Standard::kGost27843;
  SigmaMethod sigma = SigmaMethod::kFormula;
  double k = 3.0;
  AxisKind kind = AxisKind::kLinear;
  std::vector<PositionStats> positions;
  bool bidirectional = false;

  std::optional<Span> accuracy_up;               // A↑
  std::optional<Span> accuracy_down;             // A↓
  std::optional<Span> accuracy;                  // A (needs both directions)
  std::optional<Extreme> repeatability_up;       // R↑ = max R_j↑
  std::optional<Extreme> repeatability_down;     // R↓
  std::optional<Extreme> repeatability;          // R_max (GOST) / R (ISO) = max R_j
  std::optional<double> mean_repeatability;      // R̄ (GOST formula (9))
  std::optional<Extreme> reversal_max;           // B_max (GOST) / B (ISO) = max |B_j| (value ≥ 0)
  std::optional<double> reversal_mean;           // B̄ (signed mean of B_j)
  std::optional<Span> systematic_up;             // E↑ (ISO)
  std::optional<Span> systematic_down;           // E↓ (ISO)
  std::optional<Span> systematic;                // E (ISO)
  std::optional<Span> mean_bidirectional_range;  // M (ISO)
  std::optional<PositioningUncertainty> uncertainty;  // linear axes with a stated instrument
  std::vector<std::string> warnings;
};

/// Evaluates grouped readings. A failure (kInputInvalid, naming the line) when the range method is
/// chosen and a position has a number of approaches outside 5..10 (the a_n table of GOST
/// formula (6)).
Expected<PositioningResult> EvaluatePositioning(const PositioningSet& set,
                                                const EvaluationOptions& options);

}  // namespace volcomp::metrology
