// Implausible magnitudes and outliers in positioning readings.
#include "volcomp/metrology/reading_checks.hpp"

#include <algorithm>
#include <cmath>

#include "volcomp/metrology/statistics.hpp"
#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

std::string Num(double v) { return report::FormatNumber(v); }

std::string At(const PositioningData& d, std::size_t line) {
  return d.source + ":" + std::to_string(line) + ": ";
}

// The unit of a measurement column, from its name ("deviation_mm" -> "mm").
std::string ColumnUnit(const std::string& column) {
  const std::size_t u = column.rfind('_');
  return u == std::string::npos ? std::string() : column.substr(u + 1);
}

// What the readings probably are when their magnitude is implausible for `column`.
std::string TooLargeHint(const PositioningData& d) {
  const std::string unit = ColumnUnit(d.column);
  if (unit == "mm") return "if the readings are in µm, name the column deviation_um";
  if (unit == "deg") return "if the readings are in arc-seconds, name the column deviation_arcsec";
  return "check the instrument's unit and the column name";
}

std::vector<std::string> MagnitudeWarnings(const PositioningData& d, double travel) {
  std::vector<std::string> w;
  if (d.readings.empty()) return w;
  const bool linear = d.kind == AxisKind::kLinear;
  const char* unit = linear ? "µm" : "″";
  const double bound = PlausibleDeviationBound(d.kind, travel);
  const PositioningReading* first = nullptr;
  std::size_t above = 0;
  double largest = 0.0;
  for (const auto& r : d.readings) {
    largest = std::max(largest, std::fabs(r.deviation));
    if (std::fabs(r.deviation) > bound) {
      if (first == nullptr) first = &r;
      ++above;
    }
  }
  if (first != nullptr) {
    const std::string basis =
        linear ? "the larger of 1 mm and 1 µm per mm of the " + Num(travel) + " mm travel" : "1°";
    w.push_back(At(d, first->line) + "column \"" + d.column + "\": a deviation of " +
                Num(first->deviation / d.column_scale) + " " + ColumnUnit(d.column) + " (" +
                Num(first->deviation) + " " + unit + ") is beyond the plausible " + Num(bound) +
                " " + unit + " (" + basis + "); " + std::to_string(above) + " of " +
                std::to_string(d.readings.size()) + " readings are; " + TooLargeHint(d));
  }
  const double small = linear ? 0.01 : 0.001;
  if (largest > 0.0 && largest < small && d.column_scale == 1.0) {
    w.push_back(
        At(d, d.readings.front().line) + "column \"" + d.column + "\": every reading is below " +
        Num(small) + " " + unit + "; if they are in " +
        (linear ? "mm, name the column deviation_mm" : "degrees, name the column deviation_deg"));
  }
  return w;
}

void SeriesOutlier(const PositioningData& d,
                   const TargetPosition& p,
                   const ApproachSeries& s,
                   Direction dir,
                   double alpha,
                   std::vector<std::string>* w) {
  const int n = static_cast<int>(s.size());
  if (n < 3) return;
  const double mean = Mean(s.deviations);
  const double sd = SampleStdDev(s.deviations);
  if (!(sd > 0.0)) return;
  std::size_t worst = 0;
  for (std::size_t i = 1; i < s.deviations.size(); ++i) {
    if (std::fabs(s.deviations[i] - mean) > std::fabs(s.deviations[worst] - mean)) worst = i;
  }
  const double g = std::fabs(s.deviations[worst] - mean) / sd;
  const double g_crit = GrubbsCritical(n, alpha);
  if (!(g > g_crit)) return;
  const char* unit = d.kind == AxisKind::kLinear ? " µm" : "″";
  w->push_back(At(d, s.lines[worst]) + "reading " + Num(s.deviations[worst]) + unit +
               " at target " + Num(p.target) + " " + TargetUnit(d.kind) + " " +
               DirectionSymbol(dir) + " run " + std::to_string(s.runs[worst]) +
               " is an outlier by Grubbs' test at " + Num(100.0 * (1.0 - alpha)) +
               " % (G = " + report::FormatFixed(g, 3) + " > " + report::FormatFixed(g_crit, 3) +
               " for n = " + std::to_string(n) + "; mean of the others " +
               report::FormatFixed((mean * n - s.deviations[worst]) / (n - 1), 2) + unit +
               "); check the reading and its series: it enters every statistic");
}

}  // namespace

double PlausibleDeviationBound(AxisKind kind, double travel) {
  if (kind == AxisKind::kRotary) return 3600.0;
  return std::max(1000.0, 1.0 * std::fabs(travel));
}

std::vector<std::string> CheckReadings(const PositioningData& data,
                                       const PositioningSet& set,
                                       const ReadingCheckOptions& options) {
  double travel = 0.0;
  if (!set.positions.empty()) travel = set.positions.back().target - set.positions.front().target;
  if (options.travel) travel = *options.travel;
  std::vector<std::string> w = MagnitudeWarnings(data, travel);
  for (const auto& p : set.positions) {
    SeriesOutlier(data, p, p.up, Direction::kUp, options.outlier_alpha, &w);
    SeriesOutlier(data, p, p.down, Direction::kDown, options.outlier_alpha, &w);
  }
  return w;
}

}  // namespace volcomp::metrology
