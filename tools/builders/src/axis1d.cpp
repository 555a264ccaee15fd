// AXIS1D tables from positioning tests (see axis1d.hpp).
#include "volcomp/builders/axis1d.hpp"

#include <cmath>

namespace volcomp::builders {
namespace {

// Deviation at position p: linear between test positions, held beyond them.
double DeviationAt(const std::vector<double>& pos, const std::vector<double>& dev, double p) {
  if (!(p > pos.front())) return dev.front();
  if (!(p < pos.back())) return dev.back();
  std::size_t lo = 0, hi = pos.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    if (pos[mid] <= p) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const double t = (p - pos[lo]) / (pos[hi] - pos[lo]);
  return dev[lo] + t * (dev[hi] - dev[lo]);
}

// Correction at t: q with q + dev(q)·scale = t; returns q − t in deviation units.
double CorrectionAt(const std::vector<double>& pos,
                    const std::vector<double>& dev,
                    double scale,
                    double t,
                    double* residual) {
  double q = t;
  for (int i = 0; i < 100; ++i) {
    const double next = t - DeviationAt(pos, dev, q) * scale;
    const double step = std::fabs(next - q);
    q = next;
    if (step <= 1e-12 * std::fmax(1.0, std::fabs(t))) break;
  }
  *residual = std::fmax(*residual, std::fabs(q + DeviationAt(pos, dev, q) * scale - t) / scale);
  return (q - t) / scale;
}

}  // namespace

Expected<Axis1dTable> BuildAxis1d(const model::PositioningData& data,
                                  const Axis1dOptions& options) {
  const auto invalid = [](const char* message) { return Fail(Error::kInvalidArgument, message); };
  const std::size_t n = data.position.size();
  if (n < 2 || data.dev_forward.size() != n) {
    return invalid("need at least 2 positions with forward deviations");
  }
  if (!data.dev_reverse.empty() && data.dev_reverse.size() != n) {
    return invalid("reverse deviations do not match the positions");
  }
  if (options.reverse != ReverseMode::kTables && data.dev_reverse.empty()) {
    return invalid("backlash or mean tables need reverse deviations");
  }
  const double lo = data.position.front(), hi = data.position.back();
  double spacing = options.spacing;
  if (!(spacing > 0.0)) {
    spacing = data.position[1] - data.position[0];
    for (std::size_t i = 1; i < n; ++i) {
      spacing = std::fmin(spacing, data.position[i] - data.position[i - 1]);
    }
  }
  double origin = lo;
  if (options.unit_per_step > 0.0) {
    const double o_steps = lo / options.unit_per_step;
    if (std::fabs(o_steps - std::round(o_steps)) > 1e-6 * std::fmax(1.0, std::fabs(o_steps))) {
      return invalid("the first test position is not a whole number of steps");
    }
    origin = std::round(o_steps) * options.unit_per_step;
    spacing = std::fmax(1.0, std::round(spacing / options.unit_per_step)) * options.unit_per_step;
  }
  const double cells = std::ceil((hi - origin) / spacing - 1e-9);
  const std::size_t nodes = static_cast<std::size_t>(cells < 1 ? 1 : cells) + 1;

  // µm → mm or arcsec → deg: corrections are computed in position units.
  const double scale = data.rotary ? 1.0 / 3600.0 : 1e-3;
  std::vector<double> fwd = data.dev_forward, rev = data.dev_reverse;
  Axis1dTable t;
  t.origin = origin;
  t.spacing = spacing;
  if (options.reverse == ReverseMode::kMean) {
    for (std::size_t i = 0; i < n; ++i) fwd[i] = 0.5 * (fwd[i] + rev[i]);
  }
  if (options.reverse == ReverseMode::kBacklash) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += fwd[i] - rev[i];
    t.backlash = sum / static_cast<double>(n);
  }
  for (std::size_t i = 0; i < nodes; ++i) {
    const double p = origin + spacing * static_cast<double>(i);
    t.forward.push_back(CorrectionAt(data.position, fwd, scale, p, &t.max_residual));
    if (options.reverse == ReverseMode::kTables && !rev.empty()) {
      t.reverse.push_back(CorrectionAt(data.position, rev, scale, p, &t.max_residual));
    }
  }
  return t;
}

}  // namespace volcomp::builders
