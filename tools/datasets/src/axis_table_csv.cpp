// Axis error tables from CSV (see axis_table_csv.hpp for the format).
#include "volcomp/datasets/axis_table_csv.hpp"

#include <utility>
#include <vector>

namespace volcomp::datasets {
namespace {

using tools::CsvTable;

constexpr double kUradPerArcsec = 4.84813681109536;

struct AngleColumn {
  std::string name;
  double to_urad;
};

// The one column of an angle (ea, eb or ec) and its unit.
Expected<AngleColumn> FindAngle(const CsvTable& csv, const std::string& stem) {
  static const std::pair<const char*, double> kUnits[] = {
      {"_urad", 1.0}, {"_mrad", 1000.0}, {"_um_per_mm", 1000.0}, {"_arcsec", kUradPerArcsec}};
  AngleColumn found{"", 0};
  for (const auto& u : kUnits) {
    const std::string name = stem + u.first;
    if (csv.find(name)) {
      if (!found.name.empty()) {
        return Fail(csv.LineFailure(csv.header_line(), "columns \"" + found.name + "\" and \"" +
                                                           name + "\" give the same angle twice"));
      }
      found = {name, u.second};
    }
  }
  if (found.name.empty()) {
    return Fail(csv.LineFailure(
        csv.header_line(), "missing column \"" + stem + "_urad\" (or _mrad, _um_per_mm, _arcsec)"));
  }
  return found;
}

}  // namespace

Expected<model::AxisErrorTable> AxisTableFromCsv(const CsvTable& csv) {
  for (const char* c : {"position_mm", "ex_um", "ey_um", "ez_um"}) VOLCOMP_TRY(csv.Require(c));
  static const char* const kStems[3] = {"ea", "eb", "ec"};
  AngleColumn angles[3];
  for (int a = 0; a < 3; ++a) {
    VOLCOMP_TRY_ASSIGN(angles[a], FindAngle(csv, kStems[a]));
  }
  std::vector<double> pos;
  std::vector<model::AxisErrorSample> rows;
  for (const tools::CsvRow& r : csv.rows()) {
    VOLCOMP_TRY_ASSIGN(const double p, r.Number("position_mm"));
    if (!pos.empty() && !(p > pos.back())) {
      return Fail(csv.LineFailure(r.line(), "positions must increase from row to row"));
    }
    pos.push_back(p);
    tools::CsvFields f(r);
    model::AxisErrorSample s;
    s.linear_um = {f.Number("ex_um"), f.Number("ey_um"), f.Number("ez_um")};
    for (int a = 0; a < 3; ++a) s.angular_urad[a] = f.Number(angles[a].name) * angles[a].to_urad;
    VOLCOMP_TRY(f.status());
    rows.push_back(s);
  }
  if (pos.size() < 2) {
    return Fail(csv.LineFailure(csv.header_line(), "an axis table needs at least 2 rows"));
  }
  auto table = model::AxisErrorTable::Create(std::move(pos), std::move(rows));
  if (!table.ok()) return Fail(Error::kInputInvalid, csv.source() + ": " + table.error().message);
  return table;
}

Expected<model::AxisErrorTable> LoadAxisTableCsv(const std::string& path) {
  VOLCOMP_TRY_ASSIGN(const CsvTable csv, CsvTable::ReadFile(path));
  return AxisTableFromCsv(csv);
}

}  // namespace volcomp::datasets
