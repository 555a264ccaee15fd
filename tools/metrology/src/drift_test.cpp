// Reading and evaluating a thermal drift test.
#include "volcomp/metrology/drift_test.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace volcomp::metrology {
namespace {

const char* const kFixedColumns[] = {"time_s", "axis", "position_mm", "deviation_um"};

bool IsChannelColumn(const std::string& c) {
  return c.size() >= 4 && c.compare(0, 2, "T_") == 0 && c.compare(c.size() - 2, 2, "_C") == 0;
}

bool IsNameCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

std::string Mm(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// The header's channels, checked.
Expected<std::vector<DriftChannel>> ReadChannels(const tools::CsvTable& table) {
  for (const char* c : kFixedColumns) VOLCOMP_TRY(table.Require(c));
  std::vector<DriftChannel> channels;
  for (const std::string& column : table.header()) {
    bool fixed = false;
    for (const char* c : kFixedColumns) fixed = fixed || column == c;
    if (fixed) continue;
    if (!IsChannelColumn(column)) {
      return Fail(table.LineFailure(table.header_line(),
                                    "unknown column \"" + column +
                                        "\": expected time_s, axis, position_mm, deviation_um and "
                                        "one T_<name>_C column per temperature channel"));
    }
    DriftChannel ch{column.substr(2, column.size() - 4), column};
    if (ch.name.empty() || !std::all_of(ch.name.begin(), ch.name.end(), IsNameCharacter)) {
      return Fail(table.LineFailure(table.header_line(),
                                    "column \"" + column +
                                        "\": a channel name (between T_ and _C) must be one or "
                                        "more letters, digits or '_'"));
    }
    if (channels.size() == kMaxDriftChannels) {
      return Fail(table.LineFailure(table.header_line(),
                                    "column \"" + column + "\": too many temperature channels (" +
                                        std::to_string(kMaxDriftChannels) +
                                        " at most: the board's channels 0..7)"));
    }
    channels.push_back(ch);
  }
  return channels;
}

// The axis letter of a row, upper case; a failure for a rotary or unknown axis.
Expected<char> AxisOf(const tools::CsvTable& table, const tools::CsvRow& row) {
  VOLCOMP_TRY_ASSIGN(std::string text, row.Text("axis"));
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  const char c = text.size() == 1 ? static_cast<char>(std::toupper(text[0])) : '\0';
  if (c == 'A' || c == 'B' || c == 'C') {
    return Fail(table.LineFailure(row.line(), "column \"axis\": \"" + text +
                                                  "\" is a rotary axis: the drift test takes "
                                                  "linear axes (X, Y, Z, U, V, W)"));
  }
  if (std::string("XYZUVW").find(c) == std::string::npos || c == '\0') {
    return Fail(table.LineFailure(
        row.line(), "column \"axis\": \"" + text + "\" is not an axis (X, Y, Z, U, V or W)"));
  }
  return c;
}

// Linear interpolation of a point's drift at time t (within its readings).
double DriftAt(const DriftPointResult& p, double t) {
  const auto it = std::lower_bound(p.time_s.begin(), p.time_s.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - p.time_s.begin());
  if (i == 0) return p.drift_um.front();
  if (i == p.time_s.size()) return p.drift_um.back();
  const double t0 = p.time_s[i - 1], t1 = p.time_s[i];
  const double f = (t - t0) / (t1 - t0);
  return p.drift_um[i - 1] + f * (p.drift_um[i] - p.drift_um[i - 1]);
}

DriftPointResult EvaluatePoint(const DriftPoint& point) {
  DriftPointResult r;
  r.position_mm = point.position_mm;
  const double first = point.readings.front().deviation_um;
  double lo = 0, hi = 0;
  for (const DriftReading& reading : point.readings) {
    const double d = reading.deviation_um - first;
    r.time_s.push_back(reading.time_s);
    r.drift_um.push_back(d);
    if (std::fabs(d) > std::fabs(r.max_drift_um)) {
      r.max_drift_um = d;
      r.max_drift_time_s = reading.time_s;
    }
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  if (r.max_drift_um == 0) r.max_drift_time_s = r.time_s.front();
  r.range_um = hi - lo;
  r.final_drift_um = r.drift_um.back();
  // The rate window: the last hour of the point's readings, at least its last two readings.
  const double t_end = r.time_s.back();
  std::size_t from = r.time_s.size();
  while (from > 0 && r.time_s[from - 1] >= t_end - kDriftRateWindow_s) --from;
  from = std::min(from, r.time_s.size() - 2);
  const std::vector<double> t(r.time_s.begin() + static_cast<std::ptrdiff_t>(from), r.time_s.end());
  const std::vector<double> d(r.drift_um.begin() + static_cast<std::ptrdiff_t>(from),
                              r.drift_um.end());
  r.rate_um_per_h = LeastSquaresSlope(t, d) * 3600.0;
  r.rate_from_s = t.front();
  r.rate_readings = t.size();
  return r;
}

DriftAxisResult EvaluateAxis(const DriftAxis& axis, std::vector<std::string>* warnings) {
  DriftAxisResult r;
  r.name = axis.name;
  double sum = 0;
  for (const DriftPoint& p : axis.points) {
    r.points.push_back(EvaluatePoint(p));
    sum += p.position_mm;
  }
  r.mean_position_mm = sum / static_cast<double>(axis.points.size());
  // The common span of the points' readings.
  double from = r.points.front().time_s.front(), to = r.points.front().time_s.back();
  for (const DriftPointResult& p : r.points) {
    from = std::max(from, p.time_s.front());
    to = std::min(to, p.time_s.back());
  }
  std::vector<double> x;
  for (const DriftPointResult& p : r.points) x.push_back(p.position_mm);
  for (double t : r.points.front().time_s) {
    if (t < from || t > to) continue;
    std::vector<double> y;
    for (const DriftPointResult& p : r.points) y.push_back(DriftAt(p, t));
    DriftComponents c;
    c.time_s = t;
    double mean = 0;
    for (double v : y) mean += v;
    c.offset_um = mean / static_cast<double>(y.size());  // the line's value at the mean position
    c.slope_um_per_m = LeastSquaresSlope(x, y) * 1000.0;
    r.components.push_back(c);
    if (!r.max_offset || std::fabs(c.offset_um) > std::fabs(r.max_offset->offset_um)) {
      r.max_offset = c;
    }
    if (!r.max_slope || std::fabs(c.slope_um_per_m) > std::fabs(r.max_slope->slope_um_per_m)) {
      r.max_slope = c;
    }
  }
  if (r.components.empty()) {
    warnings->push_back(std::string("axis ") + axis.name +
                        ": the points' readings do not overlap in time: no offset and slope "
                        "components");
  } else {
    r.final_components = r.components.back();
  }
  return r;
}

}  // namespace

double LeastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.empty()) return 0;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0 ? sxy / sxx : 0.0;
}

Expected<DriftRecord> ReadDriftCsv(const tools::CsvTable& table) {
  DriftRecord rec;
  rec.source = table.source();
  rec.conditions = ConditionsFromPreamble(table);
  VOLCOMP_TRY_ASSIGN(rec.channels, ReadChannels(table));
  if (table.rows().empty()) {
    return Fail(table.LineFailure(table.header_line(), "no readings after the header"));
  }
  for (const tools::CsvRow& row : table.rows()) {
    DriftReading reading;
    reading.line = row.line();
    VOLCOMP_TRY_ASSIGN(reading.time_s, row.Number("time_s"));
    VOLCOMP_TRY_ASSIGN(const char name, AxisOf(table, row));
    VOLCOMP_TRY_ASSIGN(const double position, row.Number("position_mm"));
    VOLCOMP_TRY_ASSIGN(reading.deviation_um, row.Number("deviation_um"));
    for (const DriftChannel& ch : rec.channels) {
      VOLCOMP_TRY_ASSIGN(const double t, row.Number(ch.column));
      reading.temperature_C.push_back(t);
    }
    rec.time_s.push_back(reading.time_s);
    rec.temperature_C.push_back(reading.temperature_C);

    auto axis = std::find_if(rec.axes.begin(), rec.axes.end(),
                             [&](const DriftAxis& a) { return a.name == name; });
    if (axis == rec.axes.end()) {
      rec.axes.push_back(DriftAxis{name, {}});
      axis = rec.axes.end() - 1;
    }
    auto point = std::find_if(axis->points.begin(), axis->points.end(),
                              [&](const DriftPoint& p) { return p.position_mm == position; });
    if (point == axis->points.end()) {
      axis->points.push_back(DriftPoint{position, {}});
      point = axis->points.end() - 1;
    }
    if (!point->readings.empty() && !(reading.time_s > point->readings.back().time_s)) {
      return Fail(table.LineFailure(
          row.line(), "column \"time_s\": " + Mm(reading.time_s) + " s does not follow " +
                          Mm(point->readings.back().time_s) + " s of the previous reading of " +
                          std::string(1, name) + " " + Mm(position) + " mm (line " +
                          std::to_string(point->readings.back().line) +
                          "): a point's readings must be in increasing time"));
    }
    point->readings.push_back(std::move(reading));
  }
  for (DriftAxis& axis : rec.axes) {
    if (axis.points.size() < 2) {
      return Fail(table.LineFailure(
          axis.points.front().readings.front().line,
          std::string("axis ") + axis.name + " has one point (" +
              Mm(axis.points.front().position_mm) +
              " mm): the drift test reads 2 or more points per axis (offset and slope)"));
    }
    for (const DriftPoint& p : axis.points) {
      if (p.readings.size() < 2) {
        return Fail(table.LineFailure(p.readings.front().line,
                                      std::string("point ") + axis.name + " " + Mm(p.position_mm) +
                                          " mm is read only once: a drift needs 2 or more "
                                          "readings of every point"));
      }
    }
    std::sort(axis.points.begin(), axis.points.end(), [](const DriftPoint& a, const DriftPoint& b) {
      return a.position_mm < b.position_mm;
    });
  }
  return rec;
}

DriftEvaluation EvaluateDrift(const DriftRecord& record) {
  DriftEvaluation ev;
  ev.source = record.source;
  ev.conditions = record.conditions;
  ev.readings = record.time_s.size();
  ev.log_time_s = record.time_s;
  ev.log_temperature_C = record.temperature_C;
  ev.start_s = *std::min_element(record.time_s.begin(), record.time_s.end());
  ev.end_s = *std::max_element(record.time_s.begin(), record.time_s.end());
  for (const DriftAxis& axis : record.axes) ev.axes.push_back(EvaluateAxis(axis, &ev.warnings));
  for (std::size_t j = 0; j < record.channels.size(); ++j) {
    ChannelRise c;
    c.name = record.channels[j].name;
    c.number = j;
    // First and last in time (the rows need not be in time order across points).
    std::size_t first = 0, last = 0;
    c.min_C = c.max_C = record.temperature_C[0][j];
    for (std::size_t i = 0; i < record.time_s.size(); ++i) {
      const double t = record.temperature_C[i][j];
      if (record.time_s[i] < record.time_s[first]) first = i;
      if (record.time_s[i] >= record.time_s[last]) last = i;
      c.min_C = std::min(c.min_C, t);
      c.max_C = std::max(c.max_C, t);
    }
    c.first_C = record.temperature_C[first][j];
    c.last_C = record.temperature_C[last][j];
    c.rise_K = c.last_C - c.first_C;
    ev.channels.push_back(c);
  }
  return ev;
}

std::optional<EnvironmentalVariation> LargestDriftRange(const DriftEvaluation& ev) {
  std::optional<EnvironmentalVariation> out;
  for (const auto& axis : ev.axes) {
    for (const auto& p : axis.points) {
      if (p.time_s.size() < 2 || (out && p.range_um <= out->range_um)) continue;
      out = EnvironmentalVariation{p.range_um, axis.name, p.position_mm,
                                   p.time_s.back() - p.time_s.front()};
    }
  }
  return out;
}

}  // namespace volcomp::metrology
