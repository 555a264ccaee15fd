// Grouping and checking of positioning readings.
#include "volcomp/metrology/positioning_data.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

namespace volcomp::metrology {
namespace {

std::string Num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string TargetText(double target, AxisKind kind) {
  return Num(target) + (kind == AxisKind::kLinear ? " mm" : "°");
}

Unexpected<Failure> LineError(const PositioningData& d, std::size_t line, const std::string& msg) {
  return Fail(Error::kInputInvalid, d.source + ":" + std::to_string(line) + ": " + msg);
}

std::string RunList(const std::vector<int>& runs) {
  std::string s;
  for (int r : runs) s += (s.empty() ? "" : ", ") + std::to_string(r);
  return s;
}

using SeriesKey = std::pair<int, Direction>;  // (run, direction)

}  // namespace

Expected<PositioningSet> GroupReadings(const PositioningData& data,
                                       const GroupingOptions& options) {
  if (data.readings.empty()) return Fail(Error::kInputInvalid, data.source + ": no readings");
  const AxisKind kind = data.kind;

  // Duplicates: the same target, direction and run twice.
  std::map<std::tuple<double, Direction, int>, std::size_t> seen;
  for (const auto& r : data.readings) {
    if (r.run < 1) {
      return LineError(data, r.line, "run index " + std::to_string(r.run) + " must be 1 or more");
    }
    const auto key = std::make_tuple(r.target, r.direction, r.run);
    const auto it = seen.find(key);
    if (it != seen.end()) {
      return LineError(data, r.line,
                       "target " + TargetText(r.target, kind) + " " + DirectionSymbol(r.direction) +
                           " run " + std::to_string(r.run) + " is given twice (also on line " +
                           std::to_string(it->second) + ")");
    }
    seen.emplace(key, r.line);
  }

  // Targets per series (run, direction) and the series count per target.
  std::map<SeriesKey, std::set<double>> series_targets;
  std::map<double, std::set<SeriesKey>> target_series;
  for (const auto& r : data.readings) {
    series_targets[{r.run, r.direction}].insert(r.target);
    target_series[r.target].insert({r.run, r.direction});
  }
  const std::size_t n_series = series_targets.size();
  std::set<double> reference;
  for (const auto& [t, s] : target_series) {
    if (2 * s.size() >= n_series) reference.insert(t);
  }
  // Positions that differ between runs: a series uses a target outside the reference set while
  // it lacks a reference target.
  for (const auto& r : data.readings) {
    if (reference.count(r.target)) continue;
    const auto& own = series_targets[{r.run, r.direction}];
    double nearest = 0.0;
    bool found = false;
    for (double t : reference) {
      if (own.count(t)) continue;
      if (!found || std::fabs(t - r.target) < std::fabs(nearest - r.target)) nearest = t;
      found = true;
    }
    if (found) {
      return LineError(data, r.line,
                       "run " + std::to_string(r.run) + " " + DirectionSymbol(r.direction) +
                           " has target " + TargetText(r.target, kind) +
                           " where the other runs have " + TargetText(nearest, kind) +
                           "; target positions must be the same in every run");
    }
  }

  PositioningSet set;
  set.source = data.source;
  set.kind = kind;
  std::map<double, TargetPosition> by_target;
  // Readings sorted by run so each series is in run order.
  std::vector<const PositioningReading*> sorted;
  for (const auto& r : data.readings) sorted.push_back(&r);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto* a, const auto* b) { return a->run < b->run; });
  for (const auto* r : sorted) {
    TargetPosition& p = by_target[r->target];
    p.target = r->target;
    ApproachSeries& s = r->direction == Direction::kUp ? p.up : p.down;
    s.deviations.push_back(r->deviation);
    s.runs.push_back(r->run);
    s.lines.push_back(r->line);
    (r->direction == Direction::kUp ? set.has_up : set.has_down) = true;
  }
  for (auto& [t, p] : by_target) set.positions.push_back(std::move(p));

  // Missing direction at some positions.
  for (const auto& p : set.positions) {
    const ApproachSeries& any = p.up.empty() ? p.down : p.up;
    const std::size_t line = any.lines.front();
    if (set.has_up && p.up.empty()) {
      return LineError(data, line,
                       "missing direction: target " + TargetText(p.target, kind) +
                           " has no ↑ approaches while other targets have; both directions are "
                           "needed at every target for bidirectional values");
    }
    if (set.has_down && p.down.empty()) {
      return LineError(data, line,
                       "missing direction: target " + TargetText(p.target, kind) +
                           " has no ↓ approaches while other targets have; both directions are "
                           "needed at every target for bidirectional values");
    }
  }
  if (!(set.has_up && set.has_down)) {
    set.warnings.push_back(std::string("only ") + (set.has_up ? "↑" : "↓") +
                           " approaches in the data: unidirectional values only");
  }

  // Approach counts.
  std::set<int> all_runs[2];
  for (const auto& r : data.readings) all_runs[r.direction == Direction::kUp ? 0 : 1].insert(r.run);
  for (const auto& p : set.positions) {
    for (int d = 0; d < 2; ++d) {
      const ApproachSeries& s = d == 0 ? p.up : p.down;
      if (s.empty()) continue;
      const char* sym = d == 0 ? "↑" : "↓";
      const std::string what = "target " + TargetText(p.target, kind) + " " + sym + " has " +
                               std::to_string(s.size()) + " approach" +
                               (s.size() == 1 ? "" : "es") + " (runs " + RunList(s.runs) + ")";
      if (s.size() < 2) {
        return LineError(data, s.lines.front(),
                         what + "; at least 2 are needed for a standard deviation");
      }
      if (static_cast<int>(s.size()) < options.min_approaches) {
        const std::string msg = what + "; GOST 27843-88 §2.10 and ISO 230-2 require at least " +
                                std::to_string(options.min_approaches);
        if (!options.allow_few_approaches) return LineError(data, s.lines.front(), msg);
        set.warnings.push_back(data.source + ":" + std::to_string(s.lines.front()) + ": " + msg);
      }
      for (int run : all_runs[d]) {
        if (std::find(s.runs.begin(), s.runs.end(), run) == s.runs.end()) {
          set.warnings.push_back("target " + TargetText(p.target, kind) + " " + sym +
                                 ": no reading for run " + std::to_string(run));
        }
      }
    }
  }
  return set;
}

}  // namespace volcomp::metrology
