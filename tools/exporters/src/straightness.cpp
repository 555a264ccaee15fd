// A straightness test about its reference line (straightness.hpp).
#include "volcomp/exporters/straightness.hpp"

#include <cstddef>
#include <vector>

namespace volcomp::exporters {
namespace {

// The mean of both directions at each position (the forward error alone for one direction).
std::vector<double> Pooled(const ErrorTable& t) {
  std::vector<double> v = t.forward_um;
  if (!t.reverse_um.empty()) {
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = (v[i] + t.reverse_um[i]) / 2;
  }
  return v;
}

// The forward error at `x` (linear between the table's positions, held beyond them).
double ForwardAt(const ErrorTable& t, double x) {
  if (x <= t.position.front()) return t.forward_um.front();
  for (std::size_t i = 1; i < t.position.size(); ++i) {
    if (x <= t.position[i]) {
      const double f = (x - t.position[i - 1]) / (t.position[i] - t.position[i - 1]);
      return t.forward_um[i - 1] + f * (t.forward_um[i] - t.forward_um[i - 1]);
    }
  }
  return t.forward_um.back();
}

}  // namespace

Expected<StraightnessReference> RemoveReferenceLine(ErrorTable* table, StraightnessLine line) {
  ErrorTable& t = *table;
  if (t.rotary) {
    return Fail(Error::kInvalidArgument, "a straightness table is of a linear axis, not a rotary");
  }
  const std::size_t n = t.position.size();
  if (n < 2) return Fail(Error::kInvalidArgument, "a straightness table needs 2 or more positions");
  StraightnessReference ref;  // slope in µm per machine unit until the end
  const std::vector<double> y = Pooled(t);
  if (line == StraightnessLine::kEndPoints) {
    ref.slope_um_per_m = (y.back() - y.front()) / (t.position.back() - t.position.front());
    ref.offset_um = y.front() - ref.slope_um_per_m * t.position.front();
  } else if (line == StraightnessLine::kLeastSquares) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i) mx += t.position[i], my += y[i];
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < n; ++i) {
      sxy += (t.position[i] - mx) * (y[i] - my);
      sxx += (t.position[i] - mx) * (t.position[i] - mx);
    }
    ref.slope_um_per_m = sxy / sxx;  // positions increase: sxx > 0
    ref.offset_um = my - ref.slope_um_per_m * mx;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double l = ref.offset_um + ref.slope_um_per_m * t.position[i];
    t.forward_um[i] -= l;
    if (!t.reverse_um.empty()) t.reverse_um[i] -= l;
  }
  if (t.zero_at) {
    const double z = ForwardAt(t, *t.zero_at);
    for (double& v : t.forward_um) v -= z;
    for (double& v : t.reverse_um) v -= z;
  }
  ref.slope_um_per_m *= 1000.0 / MmPerUnit(t.unit);  // µm per machine unit → µm/m
  return ref;
}

}  // namespace volcomp::exporters
