// A positioning test evaluated as `volcomp evaluate positioning` reports it: the readings of one
// CSV table read, grouped and checked once (positioning_csv.hpp, positioning_data.hpp), evaluated
// per standard (positioning_eval.hpp), with the plan and plausibility checks
// (positioning_checks.hpp, reading_checks.hpp) and the file's test conditions. Input problems are
// failures (kInputInvalid) naming the file and line.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

struct PositioningTestOptions {
  std::vector<Standard> standards = {Standard::kGost27843};  // evaluated in this order
  SigmaMethod sigma = SigmaMethod::kFormula;                 // GOST 27843 only
  std::optional<double> axis_length_mm;  // travel for the checks (default: the targets' span)
  GroupingOptions grouping;
  // Instrument, temperatures, misalignment, drift (positioning_uncertainty.hpp). What is not set
  // here comes from the file's preamble: instrument_u_um, instrument_ppm, material temperature C,
  // drift_range_um, expansion_um_per_m_K.
  PositioningUncertaintyInputs uncertainty;
};

struct PositioningEvaluation {
  std::string source;           // the table's source (file name or "<stdin>")
  bool read_in_inches = false;  // the file's targets or readings were in inches (results: mm, µm)
  TestConditions conditions;
  AxisKind kind = AxisKind::kLinear;
  std::size_t positions = 0;               // target positions
  bool has_up = false;                     // ↑ approaches present
  bool has_down = false;                   // ↓ approaches present
  std::vector<PositioningResult> results;  // one per standard; each with its own warnings
  std::vector<std::string> warnings;       // the warnings of every result, each once
};

/// Reads, checks and evaluates the positioning readings of `table` (its preamble gives the test
/// conditions).
Expected<PositioningEvaluation> EvaluatePositioningTest(const tools::CsvTable& table,
                                                        const PositioningTestOptions& options);

/// Checks and evaluates readings already read from a file of any format (CSV, an instrument's
/// file), with that file's test conditions; the same checks and figures as above.
Expected<PositioningEvaluation> EvaluatePositioningReadings(const PositioningData& data,
                                                            const TestConditions& conditions,
                                                            const PositioningTestOptions& options);

/// The base name of the report of `ev`: "positioning_" and the axis of its test conditions, or
/// the stem of its file ("positioning_X", "positioning_x_readings").
std::string PositioningReportName(const PositioningEvaluation& ev);

}  // namespace volcomp::metrology
