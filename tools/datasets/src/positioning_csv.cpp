// Positioning tests from CSV (see positioning_csv.hpp for the layouts).
#include "volcomp/datasets/positioning_csv.hpp"

#include <exception>

#include "volcomp/metrology/mean_deviations.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::datasets {
namespace {

using tools::CsvTable;

Unexpected<Failure> TooFewTargets(const CsvTable& csv) {
  return Fail(
      csv.LineFailure(csv.header_line(), "a positioning test needs at least 2 target positions"));
}

}  // namespace

Expected<model::PositioningData> PositioningFromCsv(const CsvTable& csv,
                                                    const metrology::GroupingOptions& grouping) {
  model::PositioningData d;
  if (!csv.find("position_mm") && !csv.find("position_deg") &&
      metrology::HoldsPositioningReadings(csv)) {
    VOLCOMP_TRY_ASSIGN(const metrology::MeanDeviations m,
                       metrology::MeanDeviationsFromCsv(csv, grouping));
    d.rotary = m.kind == metrology::AxisKind::kRotary;
    d.position = m.target;
    d.dev_forward = m.mean_up;
    d.dev_reverse = m.mean_down;
    d.warnings = m.warnings;
    if (d.position.size() < 2) return TooFewTargets(csv);
    return d;
  }
  std::string pos_col = "position_mm", fwd_col = "dev_forward_um", rev_col = "dev_reverse_um";
  if (csv.find("position_deg")) {
    d.rotary = true;
    pos_col = "position_deg";
    fwd_col = "dev_forward_arcsec";
    rev_col = "dev_reverse_arcsec";
  }
  VOLCOMP_TRY(csv.Require(pos_col));
  VOLCOMP_TRY(csv.Require(fwd_col));
  const bool has_reverse = csv.find(rev_col).has_value();
  for (const tools::CsvRow& r : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const double p, r.Number(pos_col));
    if (!d.position.empty() && !(p > d.position.back())) {
      return Fail(csv.LineFailure(r.line(), "positions must increase from row to row"));
    }
    d.position.push_back(p);
    VOLCOMP_TRY_ASSIGN(const double forward, r.Number(fwd_col));
    d.dev_forward.push_back(forward);
    if (has_reverse) {
      VOLCOMP_TRY_ASSIGN(const double reverse, r.Number(rev_col));
      d.dev_reverse.push_back(reverse);
    }
  }
  if (d.position.size() < 2) return TooFewTargets(csv);
  return d;
}

Expected<model::PositioningData> LoadPositioningCsv(const std::string& path,
                                                    const metrology::GroupingOptions& grouping) {
  VOLCOMP_TRY_ASSIGN(const CsvTable csv, CsvTable::ReadFile(path));
  return PositioningFromCsv(csv, grouping);
}

}  // namespace volcomp::datasets
