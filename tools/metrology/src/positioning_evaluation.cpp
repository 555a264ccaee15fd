// A positioning test evaluated per standard, with its checks and test conditions.
#include "volcomp/metrology/positioning_evaluation.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "volcomp/metrology/positioning_checks.hpp"
#include "volcomp/metrology/positioning_csv.hpp"
#include "volcomp/metrology/reading_checks.hpp"
#include "volcomp/metrology/report_files.hpp"

namespace volcomp::metrology {
namespace {

// The budget over the targets' span (positioning_uncertainty.hpp): lengths or angles.
Expected<std::optional<PositioningUncertainty>> Uncertainty(
    const PositioningEvaluation& ev,
    const PositioningSet& set,
    const PositioningUncertaintyInputs& given,
    std::vector<std::string>* warnings) {
  VOLCOMP_TRY_ASSIGN(const PositioningUncertaintyInputs in,
                     CompleteFromPreamble(given, ev.conditions));
  double lo = set.positions.front().target, hi = lo;
  for (const auto& p : set.positions) lo = std::min(lo, p.target), hi = std::max(hi, p.target);
  return AxisUncertainty(in, set.kind, hi - lo, warnings);
}

}  // namespace

Expected<PositioningEvaluation> EvaluatePositioningTest(const tools::CsvTable& table,
                                                        const PositioningTestOptions& options) {
  VOLCOMP_TRY_ASSIGN(const PositioningData data, ReadPositioningCsv(table));
  return EvaluatePositioningReadings(data, ConditionsFromPreamble(table), options);
}

Expected<PositioningEvaluation> EvaluatePositioningReadings(const PositioningData& data,
                                                            const TestConditions& conditions,
                                                            const PositioningTestOptions& options) {
  PositioningEvaluation ev;
  ev.source = data.source;
  ev.read_in_inches = data.read_in_inches;
  ev.conditions = conditions;
  VOLCOMP_TRY_ASSIGN(const PositioningSet set, GroupReadings(data, options.grouping));
  ev.kind = set.kind;
  ev.positions = set.positions.size();
  ev.has_up = set.has_up;
  ev.has_down = set.has_down;
  ReadingCheckOptions checks;
  checks.travel = options.axis_length_mm;
  std::vector<std::string> reading_warnings = CheckReadings(data, set, checks);
  VOLCOMP_TRY_ASSIGN(const auto uncertainty,
                     Uncertainty(ev, set, options.uncertainty, &reading_warnings));
  for (const Standard s : options.standards) {
    EvaluationOptions eo;
    eo.standard = s;
    eo.sigma = options.sigma;
    VOLCOMP_TRY_ASSIGN(PositioningResult r, EvaluatePositioning(set, eo));
    r.uncertainty = uncertainty;
    for (const auto& w : reading_warnings) r.warnings.push_back(w);
    for (const auto& w : CheckPositionCount(set, s, options.axis_length_mm)) {
      r.warnings.push_back(w);
    }
    for (const auto& w : CheckCardinalAngles(set)) r.warnings.push_back(w);
    for (const auto& w : r.warnings) {
      if (std::find(ev.warnings.begin(), ev.warnings.end(), w) == ev.warnings.end()) {
        ev.warnings.push_back(w);
      }
    }
    ev.results.push_back(std::move(r));
  }
  return ev;
}

std::string PositioningReportName(const PositioningEvaluation& ev) {
  const auto axis = ev.conditions.Find("axis");
  return "positioning_" + (axis ? SafeName(*axis) : SourceStem(ev.source));
}

}  // namespace volcomp::metrology
