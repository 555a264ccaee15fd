// Least-squares fit of the thermal model to a drift test (see thermal_fit.hpp).
#include "volcomp/builders/thermal_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace volcomp::builders {
namespace {

using metrology::DriftAxis;
using metrology::DriftPoint;
using metrology::DriftRecord;

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInputInvalid, message);
}

std::string Num(double v, const char* format = "%.6g") {
  char text[48];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// The chosen channels with their references and ranges.
Expected<std::vector<ThermalFitChannel>> ChooseChannels(const DriftRecord& record,
                                                        const ThermalFitOptions& options) {
  if (record.channels.empty()) {
    return Invalid(record.source + ": no temperature channel (T_<name>_C columns): nothing to fit");
  }
  std::vector<std::size_t> chosen;
  if (options.channels.empty()) {
    for (std::size_t j = 0; j < record.channels.size(); ++j) chosen.push_back(j);
  }
  for (const std::string& name : options.channels) {
    std::size_t j = 0;
    while (j < record.channels.size() && record.channels[j].name != name) ++j;
    if (j == record.channels.size()) {
      std::string known;
      for (const auto& c : record.channels) known += (known.empty() ? "" : ", ") + c.name;
      return Invalid("--channels: \"" + name + "\" is not a channel of " + record.source + " (" +
                     known + ")");
    }
    if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) {
      return Invalid("--channels: \"" + name + "\" is given twice");
    }
    chosen.push_back(j);
  }
  std::sort(chosen.begin(), chosen.end());
  for (const auto& [name, value] : options.reference_by) {
    bool found = false;
    for (std::size_t j : chosen) found = found || record.channels[j].name == name;
    if (!found) return Invalid("--reference-C: \"" + name + "\" is not a chosen channel");
  }
  // The first reading in time of each channel.
  std::size_t first = 0;
  for (std::size_t i = 0; i < record.time_s.size(); ++i) {
    if (record.time_s[i] < record.time_s[first]) first = i;
  }
  std::vector<ThermalFitChannel> out;
  for (std::size_t j : chosen) {
    ThermalFitChannel c;
    c.name = record.channels[j].name;
    c.number = j;
    c.reference_C = record.temperature_C[first][j];
    if (options.reference_C) {
      c.reference_C = *options.reference_C;
      c.reference_given = true;
    }
    const auto by = options.reference_by.find(c.name);
    if (by != options.reference_by.end()) {
      c.reference_C = by->second;
      c.reference_given = true;
    }
    c.min_C = c.max_C = record.temperature_C[0][j];
    for (const auto& row : record.temperature_C) {
      c.min_C = std::min(c.min_C, row[j]);
      c.max_C = std::max(c.max_C, row[j]);
    }
    out.push_back(c);
  }
  return out;
}

// The name of unknown u: offset of channel u/2 or slope.
std::string TermName(const std::vector<ThermalFitChannel>& channels, std::size_t u) {
  return std::string(u % 2 == 0 ? "offset " : "slope ") + channels[u / 2].name;
}

Expected<ThermalAxisFit> FitAxis(const DriftAxis& axis,
                                 const std::vector<ThermalFitChannel>& channels,
                                 const ThermalFitOptions& options) {
  ThermalAxisFit fit;
  fit.name = axis.name;
  const std::string where = std::string("axis ") + axis.name;
  double sum = 0;
  for (const DriftPoint& p : axis.points) sum += p.position_mm;
  fit.p0_mm = sum / static_cast<double>(axis.points.size());
  for (const DriftPoint& p : axis.points) {
    fit.reach_mm = std::max(fit.reach_mm, std::fabs(p.position_mm - fit.p0_mm));
  }
  const auto travel = options.travel_mm.find(axis.name);
  if (travel != options.travel_mm.end()) {
    const double r = std::max(std::fabs(travel->second.first - fit.p0_mm),
                              std::fabs(travel->second.second - fit.p0_mm));
    fit.reach_from_image = r > fit.reach_mm;
    fit.reach_mm = std::max(fit.reach_mm, r);
  }

  // Rows: unknown 2j = offset of channel j, 2j+1 = its slope; target −drift.
  const std::size_t n = 2 * channels.size();
  std::vector<std::vector<double>> rows;
  std::vector<double> target;
  for (const DriftPoint& p : axis.points) {
    const double x_m = (p.position_mm - fit.p0_mm) / 1000.0;
    const auto& first = p.readings.front();
    for (std::size_t k = 1; k < p.readings.size(); ++k) {
      std::vector<double> row(n);
      for (std::size_t j = 0; j < channels.size(); ++j) {
        const std::size_t c = channels[j].number;
        const double dt = p.readings[k].temperature_C[c] - first.temperature_C[c];
        row[2 * j] = dt;
        row[2 * j + 1] = dt * x_m;
      }
      rows.push_back(row);
      target.push_back(-(p.readings[k].deviation_um - first.deviation_um));
    }
  }
  fit.samples = rows.size();
  // Equilibrate the columns.
  std::vector<double> scale(n, 0.0);
  for (const auto& row : rows) {
    for (std::size_t u = 0; u < n; ++u) scale[u] += row[u] * row[u];
  }
  for (std::size_t u = 0; u < n; ++u) {
    scale[u] = std::sqrt(scale[u]);
    if (!(scale[u] > 0)) {
      return Invalid(where + ": channel " + channels[u / 2].name +
                     " does not change during the test: its " + (u % 2 == 0 ? "offset" : "slope") +
                     " cannot be fitted (leave it out with --channels)");
    }
  }
  if (fit.samples < n) {
    return Invalid(where + ": " + std::to_string(fit.samples) +
                   " readings after the first of each "
                   "point for " +
                   std::to_string(n) + " unknowns (offset and slope per channel)");
  }
  std::vector<std::vector<double>> normal(n, std::vector<double>(n, 0.0));
  std::vector<double> rhs(n, 0.0);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t u = 0; u < n; ++u) {
      const double a = rows[r][u] / scale[u];
      rhs[u] += a * target[r];
      for (std::size_t v = 0; v < n; ++v) normal[u][v] += a * rows[r][v] / scale[v];
    }
  }
  const SymmetricEigen eig = EigenSymmetric(normal);
  const double lo = eig.values.front(), hi = eig.values.back();
  fit.condition = lo > 0 ? hi / lo : std::numeric_limits<double>::infinity();
  if (!(fit.condition <= options.max_condition)) {
    // The terms of the weakest direction: the combination the test does not determine.
    const std::vector<double>& v = eig.vectors.front();
    std::vector<std::string> terms, names;
    for (std::size_t u = 0; u < n; ++u) {
      if (std::fabs(v[u]) < 0.2) continue;
      terms.push_back(TermName(channels, u));
      const std::string& name = channels[u / 2].name;
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) {
      list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    std::string what;
    for (const std::string& t : terms) what += (what.empty() ? "" : ", ") + t;
    return Invalid(
        where + ": the fit is ill-conditioned (condition number of the normal equations " +
        Num(fit.condition, "%.3g") + ", limit " + Num(options.max_condition, "%.3g") + "): " +
        (names.size() > 1 ? "channels " + list + " move together in this test"
                          : "channel " + list + " does not tell its terms apart in this test") +
        " (" + what +
        " are not determined separately); leave one out with --channels, or log a test in "
        "which they differ");
  }
  // β_scaled = V Λ⁻¹ Vᵀ rhs.
  std::vector<double> beta(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    double proj = 0;
    for (std::size_t u = 0; u < n; ++u) proj += eig.vectors[k][u] * rhs[u];
    for (std::size_t u = 0; u < n; ++u) beta[u] += eig.vectors[k][u] * proj / eig.values[k];
  }
  for (std::size_t u = 0; u < n; ++u) beta[u] /= scale[u];
  for (std::size_t j = 0; j < channels.size(); ++j) {
    fit.offset_um_per_K.push_back(beta[2 * j]);
    fit.slope_um_per_K_m.push_back(beta[2 * j + 1]);
    for (int s = 0; s < 2; ++s) {
      const double c = beta[2 * j + s];
      if (std::fabs(c) > thermal::kMaxThermalCoefficient) {
        return Invalid(where + ": the fitted " + (s == 0 ? "offset " : "slope ") + Num(c, "%.4g") +
                       (s == 0 ? " µm/K" : " µm/(K·m)") + " of channel " + channels[j].name +
                       " is beyond the model's bound " + Num(thermal::kMaxThermalCoefficient) +
                       ": the test does not support a thermal model on that channel");
      }
    }
  }
  double ss_drift = 0, ss_res = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    double c = 0;
    for (std::size_t u = 0; u < n; ++u) c += rows[r][u] * beta[u];
    const double residual = c - target[r];  // correction + drift
    ss_res += residual * residual;
    ss_drift += target[r] * target[r];
    fit.residual_max_um = std::max(fit.residual_max_um, std::fabs(residual));
  }
  const double count = static_cast<double>(rows.size());
  fit.drift_rms_um = std::sqrt(ss_drift / count);
  fit.residual_rms_um = std::sqrt(ss_res / count);
  fit.explained = ss_drift > 0 ? 1.0 - ss_res / ss_drift : std::nan("");
  return fit;
}

int16_t ToCentiC(double celsius, bool up) {
  const double v = up ? std::ceil(celsius * 100.0 - 1e-9) : std::floor(celsius * 100.0 + 1e-9);
  return static_cast<int16_t>(v);
}

}  // namespace

SymmetricEigen EigenSymmetric(std::vector<std::vector<double>> a) {
  const std::size_t n = a.size();
  std::vector<std::vector<double>> v(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) v[i][i] = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (std::size_t p = 0; p < n; ++p) {
      diag += a[p][p] * a[p][p];
      for (std::size_t q = p + 1; q < n; ++q) off += a[p][q] * a[p][q];
    }
    if (off <= 1e-30 * diag || off == 0) break;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q) {
        if (a[p][q] == 0) continue;
        // The rotation that zeroes a[p][q]: t = tan φ, cot 2φ = (a_qq − a_pp) / (2 a_pq).
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::hypot(theta, 1.0));
        const double c = 1.0 / std::hypot(t, 1.0), s = t * c;
        for (std::size_t k = 0; k < n; ++k) {  // columns p, q
          const double kp = a[k][p], kq = a[k][q];
          a[k][p] = c * kp - s * kq;
          a[k][q] = s * kp + c * kq;
        }
        for (std::size_t k = 0; k < n; ++k) {  // rows p, q
          const double pk = a[p][k], qk = a[q][k];
          a[p][k] = c * pk - s * qk;
          a[q][k] = s * pk + c * qk;
        }
        for (std::size_t k = 0; k < n; ++k) {
          const double kp = v[k][p], kq = v[k][q];
          v[k][p] = c * kp - s * kq;
          v[k][q] = s * kp + c * kq;
        }
      }
    }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return a[x][x] < a[y][y]; });
  SymmetricEigen e;
  for (std::size_t i : order) {
    e.values.push_back(a[i][i]);
    std::vector<double> column(n);
    for (std::size_t k = 0; k < n; ++k) column[k] = v[k][i];
    e.vectors.push_back(column);
  }
  return e;
}

Expected<ThermalFit> FitThermalModel(const metrology::DriftRecord& record,
                                     const ThermalFitOptions& options) {
  if (!(options.max_condition >= 1)) return Invalid("the condition limit must be 1 or more");
  ThermalFit fit;
  fit.max_condition = options.max_condition;
  VOLCOMP_TRY_ASSIGN(fit.channels, ChooseChannels(record, options));
  for (const DriftAxis& axis : record.axes) {
    VOLCOMP_TRY_ASSIGN(ThermalAxisFit a, FitAxis(axis, fit.channels, options));
    fit.axes.push_back(std::move(a));
  }
  return fit;
}

Expected<thermal::ThermalModel> ToThermalModel(const ThermalFit& fit,
                                               const table::AxisInfo* axes,
                                               std::size_t axis_count) {
  thermal::ThermalModel m;
  if (axis_count < 1 || axis_count > thermal::kMaxModelAxes) {
    return Invalid("the image has " + std::to_string(axis_count) + " axes (1.." +
                   std::to_string(thermal::kMaxModelAxes) + " for a thermal model)");
  }
  m.axis_count = static_cast<uint8_t>(axis_count);
  std::string names;
  for (std::size_t i = 0; i < axis_count; ++i)
    names += (i ? ", " : "") + std::string(1, axes[i].name);
  for (const ThermalAxisFit& a : fit.axes) {
    std::size_t i = 0;
    while (i < axis_count && axes[i].name != a.name) ++i;
    if (i == axis_count) {
      return Invalid(std::string("axis ") + a.name +
                     " of the drift test is not an axis of the image (" + names + ")");
    }
    if (axes[i].kind == table::AxisKind::kRotary) {
      return Invalid(std::string("axis ") + a.name +
                     " is a rotary axis of the image: no thermal term on rotary axes");
    }
    thermal::AxisModel& x = m.axis[i];
    for (std::size_t j = 0; j < fit.channels.size(); ++j) {
      const std::size_t c = fit.channels[j].number;
      x.offset_um_per_K[c] = static_cast<float>(a.offset_um_per_K[j]);
      x.slope_um_per_K_m[c] = static_cast<float>(a.slope_um_per_K_m[j]);
      if (x.offset_um_per_K[c] != 0 || x.slope_um_per_K_m[c] != 0) {
        m.channel_mask = static_cast<uint8_t>(m.channel_mask | (1u << c));
      }
    }
    x.p0_mm = static_cast<float>(a.p0_mm);
    x.reach_mm = static_cast<float>(a.reach_mm);
  }
  for (const ThermalFitChannel& c : fit.channels) {
    for (double t : {c.reference_C, c.min_C, c.max_C}) {
      if (!(std::fabs(t) <= 327.0)) {
        return Invalid("channel " + c.name + ": " + Num(t) +
                       " °C is outside the board's temperatures (±327 °C)");
      }
    }
    m.reference_cC[c.number] = static_cast<int16_t>(std::lround(c.reference_C * 100.0));
    m.calibrated_low_cC[c.number] = ToCentiC(c.min_C, false);
    m.calibrated_high_cC[c.number] = ToCentiC(c.max_C, true);
  }
  const Status s = thermal::ValidateThermalModel(m);
  if (!s.ok()) {
    return Invalid(std::string("the fitted model is not valid: ") + ErrorText(s.error()) + " (" +
                   s.name() + ")");
  }
  return m;
}

}  // namespace volcomp::builders
