// Positioning plan checks.
#include "volcomp/metrology/positioning_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

std::string Num(double v) { return report::FormatNumber(v); }

}  // namespace

std::vector<std::string> CheckPositionCount(const PositioningSet& set,
                                            Standard standard,
                                            std::optional<double> axis_length_mm) {
  std::vector<std::string> w;
  if (set.kind != AxisKind::kLinear || set.positions.empty()) return w;
  std::vector<double> t;
  for (const auto& p : set.positions) t.push_back(p.target);
  const double span = t.back() - t.front();
  const double length = axis_length_mm ? *axis_length_mm : span;
  const std::size_t m = t.size();
  if (standard == Standard::kGost27843) {
    constexpr double kWindow = 2000.0;
    constexpr std::size_t kMin = 11;
    if (length <= kWindow) {
      if (m < kMin) {
        w.push_back("GOST 27843-88 §2.7: " + std::to_string(m) + " target positions on " +
                    Num(length) +
                    " mm of travel; at least 11 are required on any 2 m (unless "
                    "the machine's accuracy standard sets the number)");
      }
    } else {
      for (std::size_t i = 0; i < m; ++i) {
        const double end = t[i] + kWindow;
        if (end > t.front() + length + 1e-9) break;
        const auto count = static_cast<std::size_t>(
            std::upper_bound(t.begin(), t.end(), end + 1e-9) - (t.begin() + static_cast<long>(i)));
        if (count < kMin) {
          w.push_back("GOST 27843-88 §2.7: only " + std::to_string(count) +
                      " target positions between " + Num(t[i]) + " and " + Num(end) +
                      " mm; at least 11 are required on any 2 m of travel");
          break;
        }
      }
      if (w.empty() && m < static_cast<std::size_t>(std::ceil(11.0 * length / kWindow))) {
        w.push_back("GOST 27843-88 §2.7: " + std::to_string(m) + " target positions on " +
                    Num(length) + " mm; at least 11 per 2 m are required");
      }
    }
  } else {
    std::size_t need = 5;
    std::string rule;
    if (length <= 2000.0) {
      need = std::max<std::size_t>(
          5, static_cast<std::size_t>(std::ceil(5.0 * length / 1000.0 - 1e-9)));
      rule = "at least 5 per metre and 5 in total";
    } else {
      need = static_cast<std::size_t>(std::ceil(length / 250.0 - 1e-9)) + 1;
      rule = "an average interval of at most 250 mm on axes over 2000 mm";
    }
    if (m < need) {
      w.push_back("ISO 230-2:2014: " + std::to_string(m) + " target positions on " + Num(length) +
                  " mm of travel; " + rule + " gives at least " + std::to_string(need));
    }
  }
  if (axis_length_mm && span > *axis_length_mm + 1e-9) {
    w.push_back("the targets span " + Num(span) + " mm, more than the axis length " +
                Num(*axis_length_mm) + " mm given");
  }
  return w;
}

std::vector<std::string> CheckCardinalAngles(const PositioningSet& set) {
  std::vector<std::string> w;
  if (set.kind != AxisKind::kRotary || set.positions.empty()) return w;
  const double lo = set.positions.front().target, hi = set.positions.back().target;
  const bool full_turn = hi - lo >= 270.0;  // a full-turn test stops short of 360 by one step
  std::string missing;
  for (int a = 0; a < 360; a += 90) {
    bool in_range = full_turn;
    bool found = false;
    for (const auto& p : set.positions) {
      double m = std::fmod(p.target - a, 360.0);
      if (m < 0) m += 360.0;
      if (m < 1e-3 || m > 360.0 - 1e-3) found = true;
    }
    if (!full_turn) {
      for (double k = std::floor((lo - a) / 360.0); a + 360.0 * k <= hi; k += 1.0) {
        if (a + 360.0 * k >= lo - 1e-3) in_range = true;
      }
    }
    if (in_range && !found) missing += (missing.empty() ? "" : ", ") + std::to_string(a) + "°";
  }
  if (!missing.empty()) {
    w.push_back(
        "GOST 27843-88 §2.8: an angular positioning test must include 0°, 90°, 180° and "
        "270°; missing: " +
        missing);
  }
  return w;
}

}  // namespace volcomp::metrology
