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

// A preamble number (decimal comma allowed, "20,3"); absent: nullopt; not a number: a failure.
Expected<std::optional<double>> PreambleNumber(const TestConditions& c, const char* key) {
  auto text = c.Find(key);
  if (!text) return std::optional<double>();
  std::replace(text->begin(), text->end(), ',', '.');
  const auto v = tools::ParseDouble(*text);
  if (!v) {
    return Fail(Error::kInputInvalid,
                std::string("preamble \"") + key + ": " + *c.Find(key) + "\" is not a number");
  }
  return std::optional<double>(*v);
}

// The options' inputs completed from the preamble, then the budget over the targets' span; no
// instrument: no uncertainty and a warning that says what to state.
Expected<std::optional<PositioningUncertainty>> Uncertainty(const PositioningEvaluation& ev,
                                                            const PositioningSet& set,
                                                            PositioningUncertaintyInputs in,
                                                            std::vector<std::string>* warnings) {
  for (auto [value, key] : {std::pair{&in.instrument_u_um, "instrument_u_um"},
                            std::pair{&in.instrument_ppm, "instrument_ppm"},
                            std::pair{&in.material_temperature_C, "material temperature C"},
                            std::pair{&in.drift_range_um, "drift_range_um"},
                            std::pair{&in.expansion_um_per_m_K, "expansion_um_per_m_K"}}) {
    if (*value) continue;
    VOLCOMP_TRY_ASSIGN(*value, PreambleNumber(ev.conditions, key));
  }
  if (set.kind != AxisKind::kLinear) {
    warnings->push_back("no measurement uncertainty for a rotary axis (the budget is for lengths)");
    return std::optional<PositioningUncertainty>();
  }
  if (!in.stated()) {
    warnings->push_back(
        "no measurement uncertainty: state the instrument (--instrument-u-um from its "
        "calibration certificate or --instrument-ppm, or the preamble keys instrument_u_um / "
        "instrument_ppm) for U at k = 2 of E, A, M and B");
    return std::optional<PositioningUncertainty>();
  }
  double lo = set.positions.front().target, hi = lo;
  for (const auto& p : set.positions) lo = std::min(lo, p.target), hi = std::max(hi, p.target);
  VOLCOMP_TRY_ASSIGN(PositioningUncertainty u, PositioningU(in, hi - lo));
  for (const auto& n : u.notes) warnings->push_back(n);
  return std::optional<PositioningUncertainty>(std::move(u));
}

}  // namespace

Expected<PositioningEvaluation> EvaluatePositioningTest(const tools::CsvTable& table,
                                                        const PositioningTestOptions& options) {
  PositioningEvaluation ev;
  ev.source = table.source();
  ev.conditions = ConditionsFromPreamble(table);
  VOLCOMP_TRY_ASSIGN(const PositioningData data, ReadPositioningCsv(table));
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
