// AXIS1D tables from positioning tests (see axis1d.hpp).
#include "volcomp/model/axis1d.hpp"

#include <cmath>
#include <stdexcept>

#include "volcomp/metrology/mean_deviations.hpp"
#include "volcomp/metrology/positioning_csv.hpp"

namespace volcomp::model {
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

PositioningData PositioningFromCsv(const tools::CsvTable& csv,
                                   const metrology::GroupingOptions& grouping) {
  PositioningData d;
  if (!csv.find("position_mm") && !csv.find("position_deg") &&
      metrology::HoldsPositioningReadings(csv)) {
    // H3: MeanDeviationsFromCsv returns its failure; this function still throws it.
    const Expected<metrology::MeanDeviations> means =
        metrology::MeanDeviationsFromCsv(csv, grouping);
    if (!means.ok()) throw tools::InputError(means.error().message);
    const metrology::MeanDeviations& m = *means;
    d.rotary = m.kind == metrology::AxisKind::kRotary;
    d.position = m.target;
    d.dev_forward = m.mean_up;
    d.dev_reverse = m.mean_down;
    d.warnings = m.warnings;
    if (d.position.size() < 2) {
      throw csv.error(csv.header_line(), "a positioning test needs at least 2 target positions");
    }
    return d;
  }
  std::string pos_col = "position_mm", fwd_col = "dev_forward_um", rev_col = "dev_reverse_um";
  if (csv.find("position_deg")) {
    d.rotary = true;
    pos_col = "position_deg";
    fwd_col = "dev_forward_arcsec";
    rev_col = "dev_reverse_arcsec";
  }
  csv.require(pos_col);
  csv.require(fwd_col);
  const bool has_reverse = csv.find(rev_col).has_value();
  for (const tools::CsvRow& r : csv.rows()) {
    const double p = r.number(pos_col);
    if (!d.position.empty() && !(p > d.position.back())) {
      throw csv.error(r.line(), "positions must increase from row to row");
    }
    d.position.push_back(p);
    d.dev_forward.push_back(r.number(fwd_col));
    if (has_reverse) d.dev_reverse.push_back(r.number(rev_col));
  }
  if (d.position.size() < 2) {
    throw csv.error(csv.header_line(), "a positioning test needs at least 2 target positions");
  }
  return d;
}

PositioningData LoadPositioningCsv(const std::string& path,
                                   const metrology::GroupingOptions& grouping) {
  return PositioningFromCsv(tools::CsvTable::ParseFile(path), grouping);
}

Axis1dTable BuildAxis1d(const PositioningData& data, const Axis1dOptions& options) {
  const std::size_t n = data.position.size();
  if (n < 2 || data.dev_forward.size() != n) {
    throw std::invalid_argument("need at least 2 positions with forward deviations");
  }
  if (!data.dev_reverse.empty() && data.dev_reverse.size() != n) {
    throw std::invalid_argument("reverse deviations do not match the positions");
  }
  if (options.reverse != ReverseMode::kTables && data.dev_reverse.empty()) {
    throw std::invalid_argument("backlash or mean tables need reverse deviations");
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
      throw std::invalid_argument("the first test position is not a whole number of steps");
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

}  // namespace volcomp::model
