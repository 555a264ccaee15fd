// Positioning tests from CSV (see positioning_csv.hpp for the layouts).
#include "volcomp/datasets/positioning_csv.hpp"

#include "volcomp/metrology/inch.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::datasets {
namespace {

using tools::CsvTable;

// The means layout: position_mm, dev_forward_um [, dev_reverse_um]; an inch machine's
// position_in, dev_forward_uin [, dev_reverse_uin] (read into mm and µm); or the rotary columns.
Expected<model::PositioningData> MeansFromCsv(const CsvTable& csv) {
  model::PositioningData d;
  std::string pos_col = "position_mm", fwd_col = "dev_forward_um", rev_col = "dev_reverse_um";
  double mm_per_unit = 1, um_per_unit = 1;
  if (csv.find("position_deg")) {
    d.rotary = true;
    pos_col = "position_deg";
    fwd_col = "dev_forward_arcsec";
    rev_col = "dev_reverse_arcsec";
  } else if (csv.find("position_in")) {
    pos_col = "position_in";
    fwd_col = "dev_forward_uin";
    rev_col = "dev_reverse_uin";
    mm_per_unit = metrology::kMmPerInch;
    um_per_unit = metrology::kMicrometresPerMicroinch;
  }
  VOLCOMP_TRY(csv.Require(pos_col));
  VOLCOMP_TRY(csv.Require(fwd_col));
  const bool has_reverse = csv.find(rev_col).has_value();
  for (const tools::CsvRow& r : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const double p, r.Number(pos_col));
    if (!d.position.empty() && !(p * mm_per_unit > d.position.back())) {
      return Fail(csv.LineFailure(r.line(), "positions must increase from row to row"));
    }
    d.position.push_back(p * mm_per_unit);
    VOLCOMP_TRY_ASSIGN(const double forward, r.Number(fwd_col));
    d.dev_forward.push_back(forward * um_per_unit);
    if (has_reverse) {
      VOLCOMP_TRY_ASSIGN(const double reverse, r.Number(rev_col));
      d.dev_reverse.push_back(reverse * um_per_unit);
    }
  }
  if (d.position.size() < 2) {
    return Fail(
        csv.LineFailure(csv.header_line(), "a positioning test needs at least 2 target positions"));
  }
  return d;
}

}  // namespace

Expected<PositioningFile> PositioningFileFromCsv(const CsvTable& csv) {
  PositioningFile f;
  f.source = csv.source();
  f.format = PositioningFormat::kCsv;
  f.conditions = metrology::ConditionsFromPreamble(csv);
  if (csv.find("position_mm") || csv.find("position_in") || csv.find("position_deg")) {
    VOLCOMP_TRY_ASSIGN(f.means, MeansFromCsv(csv));
    f.means_in_inches = csv.find("position_in").has_value() && !csv.find("position_deg");
    f.readings_line = csv.header_line();
    return f;
  }
  if (!metrology::HoldsPositioningReadings(csv)) {
    return Fail(csv.LineFailure(
        csv.header_line(),
        "unrecognised header: expected the raw readings (target_mm, target_in or target_deg, "
        "direction, run "
        "and a measurement column such as deviation_um; or the wide layout deviation_um,1+,1-,...)"
        " or the mean deviations (position_mm, dev_forward_um [, dev_reverse_um]; inches: "
        "position_in, dev_forward_uin [, dev_reverse_uin])"));
  }
  VOLCOMP_TRY_ASSIGN(f.readings, metrology::ReadPositioningCsv(csv));
  f.readings_line = csv.header_line();
  return f;
}

Expected<model::PositioningData> PositioningFromCsv(const CsvTable& csv,
                                                    const metrology::GroupingOptions& grouping) {
  VOLCOMP_TRY_ASSIGN(const PositioningFile f, PositioningFileFromCsv(csv));
  return PositioningMeans(f, grouping);
}

Expected<model::PositioningData> LoadPositioningCsv(const std::string& path,
                                                    const metrology::GroupingOptions& grouping) {
  VOLCOMP_TRY_ASSIGN(const CsvTable csv, CsvTable::ReadFile(path));
  return PositioningFromCsv(csv, grouping);
}

}  // namespace volcomp::datasets
