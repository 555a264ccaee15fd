// Error tables for the controllers' writers (see error_table.hpp).
#include "volcomp/exporters/error_table.hpp"

#include <cmath>
#include <cstdio>

namespace volcomp::exporters {
namespace {

// Linear interpolation of `value` over the increasing `at`, x inside [at.front(), at.back()].
double Interpolate(const std::vector<double>& at, const std::vector<double>& value, double x) {
  std::size_t i = 1;
  while (i + 1 < at.size() && at[i] < x) ++i;
  const double t = (x - at[i - 1]) / (at[i] - at[i - 1]);
  return value[i - 1] + t * (value[i] - value[i - 1]);
}

double Tolerance(double x) { return 1e-9 * std::fmax(1.0, std::fabs(x)); }

}  // namespace

const char* UnitName(LengthUnit unit, bool rotary) {
  return rotary ? "deg" : unit == LengthUnit::kInch ? "in" : "mm";
}

double MmPerUnit(LengthUnit unit) { return unit == LengthUnit::kInch ? kMmPerInch : 1.0; }

double FromMm(double position_mm, LengthUnit unit) {
  if (unit == LengthUnit::kMm) return position_mm;
  return std::round(position_mm / kMmPerInch * 1e9) / 1e9;
}

double ToMachineUnits(double error_um, bool rotary, LengthUnit unit) {
  return rotary ? error_um / 3600.0 : error_um / (1000.0 * MmPerUnit(unit));
}

Expected<ErrorTable> BuildErrorTable(const model::PositioningData& data,
                                     const ErrorTableOptions& options) {
  // The test's positions (mm, deg) in the machine's unit.
  std::vector<double> p = data.position;
  if (p.size() < 2) return Fail(Error::kInvalidArgument, "fewer than 2 test positions");
  if (!data.rotary) {
    for (double& x : p) x = FromMm(x, options.unit);
  }
  const double hi = p.back();
  const char* unit = UnitName(options.unit, data.rotary);
  char msg[256];
  ErrorTable t;
  t.rotary = data.rotary;
  t.unit = options.unit;
  t.tested_to = hi;
  t.zero_at = options.zero_at;
  t.negated = options.negate;
  if (options.spacing > 0) {
    const double span = hi - p.front();
    const auto gaps = static_cast<std::size_t>(std::floor(span / options.spacing + 1e-9));
    if (gaps < 1) {
      std::snprintf(msg, sizeof msg,
                    "spacing %.6g %s is longer than the tested travel %.6g %s (from %.6g to "
                    "%.6g): give a smaller --spacing",
                    options.spacing, unit, span, unit, p.front(), hi);
      return Fail(Error::kInvalidArgument, msg);
    }
    for (std::size_t i = 0; i <= gaps; ++i) {
      t.position.push_back(p.front() + options.spacing * static_cast<double>(i));
    }
    t.spacing = options.spacing;
    t.uncovered = std::fmax(0.0, hi - t.position.back());
    if (t.uncovered <= Tolerance(hi)) t.uncovered = 0;
  } else {
    t.position = p;
    t.spacing = p[1] - p[0];
    for (std::size_t i = 2; i < p.size(); ++i) {
      if (std::fabs(p[i] - p[i - 1] - t.spacing) > Tolerance(p[i])) t.spacing = 0;
    }
  }
  for (const double x : t.position) {
    t.forward_um.push_back(Interpolate(p, data.dev_forward, x));
    if (!data.dev_reverse.empty()) t.reverse_um.push_back(Interpolate(p, data.dev_reverse, x));
  }
  if (options.zero_at) {
    const double z = *options.zero_at;
    if (z < p.front() - Tolerance(z) || z > hi + Tolerance(z)) {
      std::snprintf(msg, sizeof msg,
                    "reference position %.6g %s is outside the tested travel %.6g to %.6g %s", z,
                    unit, p.front(), hi, unit);
      return Fail(Error::kInvalidArgument, msg);
    }
    const double shift = Interpolate(p, data.dev_forward, std::fmin(std::fmax(z, p.front()), hi));
    for (double& e : t.forward_um) e -= shift;
    for (double& e : t.reverse_um) e -= shift;
  }
  if (options.negate) {
    for (double& e : t.forward_um) e = -e;
    for (double& e : t.reverse_um) e = -e;
  }
  return t;
}

Expected<double> RequireEqualSpacing(const ErrorTable& table, const std::string& controller) {
  if (table.spacing > 0) return table.spacing;
  const std::vector<double>& p = table.position;
  std::size_t i = 2;
  while (i < p.size() && std::fabs((p[i] - p[i - 1]) - (p[1] - p[0])) <= Tolerance(p[i])) ++i;
  if (i >= p.size()) return p[1] - p[0];
  const char* unit = UnitName(table.unit, table.rotary);
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "the test positions are not equally spaced (%.6g %s from %.6g to %.6g, %.6g %s "
                "from %.6g to %.6g): %s takes equally spaced points only; give --spacing to "
                "resample the test to an equal grid",
                p[1] - p[0], unit, p[0], p[1], p[i] - p[i - 1], unit, p[i - 1], p[i],
                controller.c_str());
  return Fail(Error::kInvalidArgument, msg);
}

Expected<void> RequirePointLimit(const ErrorTable& table,
                                 std::size_t limit,
                                 const std::string& controller) {
  const std::size_t n = table.position.size();
  if (n <= limit) return {};
  const double span = table.position.back() - table.position.front();
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "%zu points, %s takes at most %zu: use a --spacing of at least %.6g %s", n,
                controller.c_str(), limit, span / static_cast<double>(limit - 1),
                UnitName(table.unit, table.rotary));
  return Fail(Error::kInvalidArgument, msg);
}

}  // namespace volcomp::exporters
