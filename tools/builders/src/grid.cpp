// Correction grids: sampling, trilinear prediction, spacing choice, bounds (see grid.hpp).
#include "volcomp/builders/grid.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace volcomp::builders {
namespace {

using model::CorrectionGrid;
using model::GridAxes;
using model::GridAxis;
using model::Vec3;

constexpr double kUmPerMm = 1000.0;

// splitmix64: a small, portable, deterministic generator.
struct Rng {
  uint64_t state;
  uint64_t Next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  uint32_t Below(uint32_t n) { return static_cast<uint32_t>(Uniform() * n) % n; }
};

std::string Fmt(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), format, a, b, c, d);
  return buf;
}

double SnapToSteps(double value_mm, double step_mm) {
  const double steps = std::round(value_mm / step_mm);
  return (steps < 1.0 ? 1.0 : steps) * step_mm;
}

}  // namespace

Expected<CorrectionGrid> SampleGrid(const GridAxes& spec,
                                    const InverseMap& inverse,
                                    const ForwardMap* forward,
                                    GridSampleStats* stats) {
  CorrectionGrid g;
  g.axes = spec;
  g.correction_mm.resize(static_cast<std::size_t>(spec[0].nodes) * spec[1].nodes * spec[2].nodes);
  GridSampleStats s;
  for (uint32_t k = 0; k < spec[2].nodes; ++k) {
    for (uint32_t j = 0; j < spec[1].nodes; ++j) {
      for (uint32_t i = 0; i < spec[0].nodes; ++i) {
        const Vec3 target = g.NodePosition(i, j, k);
        VOLCOMP_TRY_ASSIGN(const Vec3 command, inverse(target));
        const Vec3 c = command - target;
        g.correction_mm[g.Index(i, j, k)] = c;
        const double c_um = MaxAbs(c) * kUmPerMm;
        if (!(c_um <= s.max_correction_um)) {  // also catches NaN
          s.max_correction_um = std::isnan(c_um) ? INFINITY : c_um;
          s.max_correction_at_mm = target;
        }
        if (forward != nullptr) {
          const double r_um = Norm((*forward)(command)-target) * kUmPerMm;
          if (!(r_um <= s.max_residual_um)) s.max_residual_um = std::isnan(r_um) ? INFINITY : r_um;
        }
      }
    }
  }
  if (stats != nullptr) *stats = s;
  return g;
}

Expected<InterpolationReport> PredictInterpolationError(const CorrectionGrid& grid,
                                                        const InverseMap& inverse,
                                                        std::size_t max_cells,
                                                        int points_per_cell,
                                                        uint64_t seed) {
  const uint32_t cx = grid.axes[0].nodes - 1, cy = grid.axes[1].nodes - 1,
                 cz = grid.axes[2].nodes - 1;
  const std::size_t cells = static_cast<std::size_t>(cx) * cy * cz;
  const bool all = cells <= max_cells;
  const std::size_t count = all ? cells : max_cells;
  Rng rng{seed};
  InterpolationReport r;
  double sum_sq = 0.0;
  for (std::size_t n = 0; n < count; ++n) {
    uint32_t i, j, k;
    if (all) {
      i = static_cast<uint32_t>(n % cx);
      j = static_cast<uint32_t>((n / cx) % cy);
      k = static_cast<uint32_t>(n / (static_cast<std::size_t>(cx) * cy));
    } else {
      i = rng.Below(cx);
      j = rng.Below(cy);
      k = rng.Below(cz);
    }
    const Vec3 base = grid.NodePosition(i, j, k);
    for (int p = 0; p <= points_per_cell; ++p) {
      Vec3 f = {0.5, 0.5, 0.5};
      if (p > 0) f = {rng.Uniform(), rng.Uniform(), rng.Uniform()};
      const Vec3 point = {base.x + f.x * grid.axes[0].spacing_mm,
                          base.y + f.y * grid.axes[1].spacing_mm,
                          base.z + f.z * grid.axes[2].spacing_mm};
      VOLCOMP_TRY_ASSIGN(const Vec3 command, inverse(point));
      const Vec3 exact = command - point;
      const double e_um = Norm(grid.Interpolate(point) - exact) * kUmPerMm;
      sum_sq += e_um * e_um;
      ++r.samples;
      if (!(e_um <= r.max_um)) {
        r.max_um = std::isnan(e_um) ? INFINITY : e_um;
        r.worst_at_mm = point;
      }
    }
  }
  r.rms_um = r.samples > 0 ? std::sqrt(sum_sq / static_cast<double>(r.samples)) : 0.0;
  return r;
}

Expected<GridAxes> MakeGridAxes(const GridBuildOptions& options,
                                const std::array<double, 3>& spacing_mm) {
  const auto invalid = [](const std::string& message) {
    return Fail(Error::kInvalidArgument, message);
  };
  GridAxes spec;
  for (int a = 0; a < 3; ++a) {
    const std::size_t ua = static_cast<std::size_t>(a);
    const char name = "XYZ"[a];
    const double step = options.step_mm[ua];
    const double lo = options.min_mm[ua], hi = options.max_mm[ua], h = spacing_mm[ua];
    if (!(step > 0.0)) return invalid(std::string("axis ") + name + ": no step size");
    if (!(hi > lo)) return invalid(std::string("axis ") + name + ": the range is empty");
    if (!(h > 0.0)) return invalid(std::string("axis ") + name + ": no spacing");
    const double h_steps = h / step, lo_steps = lo / step;
    if (std::fabs(h_steps - std::round(h_steps)) > 1e-6 * std::fmax(1.0, h_steps)) {
      return invalid(
          std::string("axis ") + name +
          Fmt(": spacing %.9g mm is not a whole number of steps (%.9g mm/step)", h, step));
    }
    if (std::fabs(lo_steps - std::round(lo_steps)) > 1e-6 * std::fmax(1.0, std::fabs(lo_steps))) {
      return invalid(
          std::string("axis ") + name +
          Fmt(": grid origin %.9g mm is not a whole number of steps (%.9g mm/step)", lo, step));
    }
    GridAxis& g = spec[ua];
    g.origin_mm = std::round(lo_steps) * step;
    g.spacing_mm = std::round(h_steps) * step;
    const double cells = std::ceil((hi - g.origin_mm) / g.spacing_mm - 1e-9);
    if (cells + 1 > options.max_nodes_per_axis) {
      return invalid(std::string("axis ") + name +
                     Fmt(": %.0f nodes exceed the limit of %.0f per axis", cells + 1,
                         options.max_nodes_per_axis));
    }
    g.nodes = static_cast<uint32_t>(cells < 1 ? 1 : cells) + 1;
  }
  const double total = static_cast<double>(spec[0].nodes) * spec[1].nodes * spec[2].nodes;
  if (total > static_cast<double>(options.max_nodes)) {
    return invalid(
        Fmt("%.0f nodes exceed the limit of %.0f", total, static_cast<double>(options.max_nodes)));
  }
  return spec;
}

Expected<GridBuildResult> BuildCorrectionGrid(const GridBuildOptions& options,
                                              const InverseMap& inverse,
                                              const ForwardMap* forward) {
  GridBuildResult result;
  const bool explicit_spacing =
      options.spacing_mm[0] > 0 && options.spacing_mm[1] > 0 && options.spacing_mm[2] > 0;
  if (explicit_spacing || options.max_interp_error_um <= 0.0) {
    std::array<double, 3> h = options.spacing_mm;
    if (!explicit_spacing) {
      for (std::size_t a = 0; a < 3; ++a) {
        h[a] = SnapToSteps(options.natural_spacing_mm[a], options.step_mm[a]);
      }
    }
    VOLCOMP_TRY_ASSIGN(const GridAxes spec, MakeGridAxes(options, h));
    VOLCOMP_TRY_ASSIGN(result.grid, SampleGrid(spec, inverse, forward, &result.stats));
    VOLCOMP_TRY_ASSIGN(result.interpolation, PredictInterpolationError(result.grid, inverse));
    result.tried.push_back({h, result.interpolation.max_um});
  } else {
    static const double kFactors[] = {8, 4, 2, 1, 0.5, 0.25, 0.125, 0.0625, 0.03125};
    bool found = false;
    std::array<double, 3> prev = {0, 0, 0};
    for (double f : kFactors) {
      std::array<double, 3> h;
      for (std::size_t a = 0; a < 3; ++a) {
        const double range = options.max_mm[a] - options.min_mm[a];
        h[a] = SnapToSteps(std::fmin(options.natural_spacing_mm[a] * f, range), options.step_mm[a]);
      }
      if (h == prev) continue;
      prev = h;
      const Expected<GridAxes> spec = MakeGridAxes(options, h);
      if (!spec.ok()) break;  // finer spacings only get larger
      VOLCOMP_TRY_ASSIGN(const CorrectionGrid g, SampleGrid(*spec, inverse));
      VOLCOMP_TRY_ASSIGN(const InterpolationReport rep, PredictInterpolationError(g, inverse));
      result.tried.push_back({h, rep.max_um});
      if (rep.max_um <= options.max_interp_error_um) {
        VOLCOMP_TRY_ASSIGN(result.grid, SampleGrid(*spec, inverse, forward, &result.stats));
        result.interpolation = rep;
        found = true;
        break;
      }
    }
    if (!found) {
      std::string msg =
          Fmt("no grid within the node limits predicts an interpolation error "
              "below %.4g µm",
              options.max_interp_error_um);
      if (!result.tried.empty()) {
        const auto& last = result.tried.back();
        msg += Fmt("; the finest tried (%.6g x %.6g x %.6g mm) predicts", last.first[0],
                   last.first[1], last.first[2]);
        msg += Fmt(" %.4g µm", last.second);
      }
      return Fail(Error::kInputInvalid, msg);
    }
  }
  const GridSampleStats& s = result.stats;
  if (s.max_correction_um > options.max_correction_um) {
    return Fail(Error::kOutOfRange,
                Fmt("correction of %.1f µm at (%.6g, %.6g, %.6g) mm", s.max_correction_um,
                    s.max_correction_at_mm.x, s.max_correction_at_mm.y, s.max_correction_at_mm.z) +
                    Fmt(" exceeds the configured bound of %.1f µm; check the input "
                        "units or raise the bound",
                        options.max_correction_um));
  }
  if (forward != nullptr && s.max_residual_um > options.max_residual_um) {
    return Fail(Error::kInputInvalid,
                Fmt("the inverse misses its target by %.4g µm at some node (limit %.4g µm)",
                    s.max_residual_um, options.max_residual_um));
  }
  return result;
}

}  // namespace volcomp::builders
