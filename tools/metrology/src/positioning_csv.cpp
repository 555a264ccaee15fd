// Positioning CSV reader: long and wide layouts.
#include "volcomp/metrology/positioning_csv.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "volcomp/metrology/inch.hpp"

namespace volcomp::metrology {
namespace {

using tools::CsvRow;
using tools::CsvTable;

// How a measurement column converts to the internal deviation unit.
struct MeasurementColumn {
  const char* name;
  AxisKind kind;
  double scale;   // value·scale = deviation (µm or arc-seconds)
  bool absolute;  // value is the measured position, not the deviation
  bool inch;      // in inches or micro-inches (converted: the results are in mm and µm)
};

// 1 in = 25.4 mm exactly (international inch, 1959): 1 in = 25400 µm, 1 µin = 0.0254 µm.
constexpr MeasurementColumn kMeasurementColumns[] = {
    {"deviation_um", AxisKind::kLinear, 1.0, false, false},
    {"deviation_mm", AxisKind::kLinear, 1000.0, false, false},
    {"measured_mm", AxisKind::kLinear, 1000.0, true, false},
    {"deviation_in", AxisKind::kLinear, kMmPerInch * 1000.0, false, true},
    {"deviation_uin", AxisKind::kLinear, kMicrometresPerMicroinch, false, true},
    {"measured_in", AxisKind::kLinear, kMmPerInch * 1000.0, true, true},
    {"deviation_arcsec", AxisKind::kRotary, 1.0, false, false},
    {"deviation_deg", AxisKind::kRotary, 3600.0, false, false},
    {"measured_deg", AxisKind::kRotary, 3600.0, true, false},
};

// A target column and what one of its units is in mm (degrees on a rotary axis).
struct TargetColumn {
  const char* name;
  AxisKind kind;
  double scale;
};

constexpr TargetColumn kTargetColumns[] = {
    {"target_mm", AxisKind::kLinear, 1.0},
    {"target_in", AxisKind::kLinear, kMmPerInch},
    {"target_deg", AxisKind::kRotary, 1.0},
};

const TargetColumn* FindTarget(const std::string& name) {
  for (const auto& c : kTargetColumns) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

bool HasTargetColumn(const CsvTable& t) {
  for (const auto& c : kTargetColumns) {
    if (t.find(c.name)) return true;
  }
  return false;
}

const MeasurementColumn* FindMeasurement(const std::string& name) {
  for (const auto& m : kMeasurementColumns) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

std::string MeasurementNames() {
  std::string s;
  for (const auto& m : kMeasurementColumns) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

Expected<double> ToDeviation(
    const CsvTable& t, const CsvRow& row, const MeasurementColumn& m, double value, double target) {
  // An absolute column's unit in the target's unit (mm or degrees): measured_in 25400 µm = 25.4 mm.
  const double unit = m.absolute ? m.scale / (m.kind == AxisKind::kLinear ? 1000.0 : 3600.0) : 1.0;
  double diff = m.absolute ? value - target / unit : value;  // in the column's unit
  if (m.absolute && m.kind == AxisKind::kRotary) {
    diff = std::remainder(diff, 360.0);  // into [-180, 180]
    if (diff == -180.0) diff = 180.0;
  }
  const double deviation = diff * m.scale;
  if (!std::isfinite(deviation) || std::fabs(deviation) > kMaxReadingMagnitude) {
    std::ostringstream s;
    const std::string name = m.name;
    s << "column \"" << name << "\": a deviation of " << diff << " "
      << name.substr(name.rfind('_') + 1) << " cannot be a reading (the limit is ±"
      << kMaxReadingMagnitude << " " << (m.kind == AxisKind::kLinear ? "µm" : "arc-seconds")
      << "); refused";
    return Fail(t.LineFailure(row.line(), s.str()));
  }
  return deviation;
}

Expected<int> ParseRun(const CsvTable& t,
                       const CsvRow& row,
                       const std::string& text,
                       const std::string& column) {
  const auto v = tools::ParseInteger(text);
  if (!v || *v < 1 || *v > 1000000) {
    return Fail(t.LineFailure(row.line(), "column \"" + column + "\": run index \"" + text +
                                              "\" is not a positive integer"));
  }
  return static_cast<int>(*v);
}

Expected<PositioningData> ReadLong(const CsvTable& t) {
  PositioningData d;
  d.source = t.source();
  const TargetColumn* target = nullptr;
  for (const auto& name : t.header()) {
    const TargetColumn* c = FindTarget(name);
    if (c == nullptr) continue;
    if (target != nullptr) {
      return Fail(t.LineFailure(t.header_line(), "both \"" + std::string(target->name) +
                                                     "\" and \"" + name + "\" columns; give one"));
    }
    target = c;
  }
  const std::string target_col = target->name;  // the caller checked there is one
  d.kind = target->kind;
  VOLCOMP_TRY(t.Require("direction"));
  VOLCOMP_TRY(t.Require("run"));
  const MeasurementColumn* meas = nullptr;
  for (const auto& name : t.header()) {
    const MeasurementColumn* m = FindMeasurement(name);
    if (!m) continue;
    if (meas) {
      return Fail(t.LineFailure(t.header_line(), "two measurement columns \"" +
                                                     std::string(meas->name) + "\" and \"" + name +
                                                     "\"; give exactly one"));
    }
    meas = m;
  }
  if (!meas) {
    return Fail(t.LineFailure(t.header_line(),
                              "missing measurement column (one of " + MeasurementNames() + ")"));
  }
  if (meas->kind != d.kind) {
    return Fail(t.LineFailure(
        t.header_line(), "column \"" + std::string(meas->name) + "\" does not fit \"" + target_col +
                             "\" (" + (d.kind == AxisKind::kLinear ? "linear" : "rotary") +
                             " axis)"));
  }
  for (const CsvRow& row : t.rows()) {
    PositioningReading r;
    r.line = row.line();
    VOLCOMP_TRY_ASSIGN(const double target_value, row.Number(target_col));
    r.target = target_value * target->scale;
    VOLCOMP_TRY_ASSIGN(const std::string direction, row.Text("direction"));
    const auto dir = ParseDirection(direction);
    if (!dir) {
      return Fail(t.LineFailure(row.line(), "column \"direction\": \"" + direction +
                                                "\" is not a direction (use +, -, up or down)"));
    }
    r.direction = *dir;
    VOLCOMP_TRY_ASSIGN(const std::string run, row.Text("run"));
    VOLCOMP_TRY_ASSIGN(r.run, ParseRun(t, row, run, "run"));
    VOLCOMP_TRY_ASSIGN(const double value, row.Number(meas->name));
    VOLCOMP_TRY_ASSIGN(r.deviation, ToDeviation(t, row, *meas, value, r.target));
    d.readings.push_back(r);
  }
  if (d.readings.empty()) {
    return Fail(t.LineFailure(t.header_line(), "no data rows after the header"));
  }
  d.column = meas->name;
  d.column_scale = meas->scale;
  d.read_in_inches = meas->inch || target->scale != 1.0;
  return d;
}

// "3+", "3-", "3up", "3down", "3↑", "3↓" -> (3, direction).
std::optional<std::pair<long long, Direction>> ParseWideColumn(const std::string& name) {
  std::size_t i = 0;
  while (i < name.size() && name[i] >= '0' && name[i] <= '9') ++i;
  if (i == 0 || i == name.size()) return std::nullopt;
  const auto j = tools::ParseInteger(name.substr(0, i));
  const auto dir = ParseDirection(name.substr(i));
  if (!j || !dir) return std::nullopt;
  return std::make_pair(*j, *dir);
}

Expected<PositioningData> ReadWide(const CsvTable& t, const MeasurementColumn& meas) {
  PositioningData d;
  d.source = t.source();
  d.kind = meas.kind;
  const auto& header = t.header();
  std::vector<std::pair<long long, Direction>> cols;
  for (std::size_t c = 1; c < header.size(); ++c) {
    const auto jd = ParseWideColumn(header[c]);
    if (!jd) {
      return Fail(t.LineFailure(t.header_line(), "column \"" + header[c] +
                                                     "\" is not a position and direction such "
                                                     "as \"3+\" or \"3-\""));
    }
    cols.push_back(*jd);
  }
  if (cols.empty()) {
    return Fail(t.LineFailure(t.header_line(), "no position columns after \"" + header[0] + "\""));
  }
  if (t.rows().empty()) {
    return Fail(t.LineFailure(t.header_line(), "no target row after the header"));
  }
  // Every row has as many fields as the header (the reader checks), so fields()[c] is safe.
  const CsvRow& target_row = t.rows().front();
  const std::vector<std::string>& target_fields = target_row.fields();
  const TargetColumn* target = FindTarget(target_fields[0]);
  if (target == nullptr || target->kind != meas.kind) {
    const std::string labels =
        meas.kind == AxisKind::kLinear ? "\"target_mm\" or \"target_in\"" : "\"target_deg\"";
    return Fail(t.LineFailure(target_row.line(), "expected the row " + labels +
                                                     " with the target positions, found \"" +
                                                     target_fields[0] + "\""));
  }
  std::vector<double> targets;
  std::map<long long, std::pair<double, std::size_t>> target_of_j;  // j -> (target, column)
  for (std::size_t c = 1; c < header.size(); ++c) {
    VOLCOMP_TRY_ASSIGN(const double p, target_row.Number(c));
    targets.push_back(p * target->scale);
    const long long j = cols[c - 1].first;
    const auto it = target_of_j.find(j);
    if (it != target_of_j.end() && it->second.first != p) {
      return Fail(
          t.LineFailure(target_row.line(), "position " + std::to_string(j) + " has target " +
                                               target_fields[c] + " in column \"" + header[c] +
                                               "\" but " + target_fields[it->second.second] +
                                               " in column \"" + header[it->second.second] + "\""));
    }
    target_of_j.emplace(j, std::make_pair(p, c));
  }
  for (std::size_t k = 1; k < t.rows().size(); ++k) {
    const CsvRow& row = t.rows()[k];
    VOLCOMP_TRY_ASSIGN(const int run, ParseRun(t, row, row.fields()[0], header[0]));
    for (std::size_t c = 1; c < header.size(); ++c) {
      if (row.fields()[c].empty()) continue;  // missing reading
      PositioningReading r;
      r.line = row.line();
      r.target = targets[c - 1];
      r.direction = cols[c - 1].second;
      r.run = run;
      VOLCOMP_TRY_ASSIGN(const double value, row.Number(c));
      VOLCOMP_TRY_ASSIGN(r.deviation, ToDeviation(t, row, meas, value, r.target));
      d.readings.push_back(r);
    }
  }
  if (d.readings.empty()) {
    return Fail(t.LineFailure(target_row.line(), "no readings after the target row"));
  }
  d.column = meas.name;
  d.column_scale = meas.scale;
  d.read_in_inches = meas.inch || target->scale != 1.0;
  return d;
}

}  // namespace

bool HoldsPositioningReadings(const CsvTable& table) {
  const auto& header = table.header();
  if (FindMeasurement(header.front()) && header.size() > 1 && ParseWideColumn(header[1])) {
    return true;
  }
  return HasTargetColumn(table);
}

Expected<PositioningData> ReadPositioningCsv(const CsvTable& table) {
  const auto& header = table.header();
  if (const MeasurementColumn* m = FindMeasurement(header.front())) {
    if (header.size() > 1 && ParseWideColumn(header[1])) return ReadWide(table, *m);
  }
  if (!HasTargetColumn(table)) {
    return Fail(table.LineFailure(
        table.header_line(),
        "unrecognised header: expected the long layout (target_mm, target_in or target_deg, "
        "direction, run "
        "and a measurement column) or the wide layout (first cell a measurement column such as "
        "deviation_um, then columns like 1+,1-,2+,...)"));
  }
  return ReadLong(table);
}

}  // namespace volcomp::metrology
