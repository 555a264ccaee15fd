// The sources of a GRID3 build (see grid_source.hpp).
#include "volcomp/builders/grid_source.hpp"

#include <algorithm>
#include <memory>

namespace volcomp::builders {
namespace {

using model::CosineSource;
using model::Vec3;

const char* CosineName(CosineSource c) {
  switch (c) {
    case CosineSource::kPrinted:
      return "printed";
    case CosineSource::kSigned:
      return "signed";
    case CosineSource::kScaled:
      return "scaled";
  }
  return "?";
}

// A method's result as the command an inverse map returns.
template <typename R>
Expected<Vec3> CommandOf(const Expected<R>& r) {
  if (!r.ok()) return Fail(r.error());
  return r->command_mm;
}

}  // namespace

GridSource ModelGridSource(const model::Model& model) {
  GridSource s;
  for (std::size_t a = 0; a < 3; ++a) {
    const model::AxisErrorTable& t = model.axes[a];
    s.min_mm[a] = t.min_mm();
    s.max_mm[a] = t.max_mm();
    double h = t.uniform_spacing_mm();
    if (!(h > 0)) {  // irregular table: its smallest row gap
      h = t.max_mm() - t.min_mm();
      for (std::size_t i = 1; i < t.size(); ++i) {
        h = std::min(h, t.position_mm(i) - t.position_mm(i - 1));
      }
    }
    s.natural_spacing_mm[a] = h;
  }
  const auto m = std::make_shared<const model::Model>(model);
  s.inverse = [m](const Vec3& t) -> Expected<Vec3> {
    return model::SolveCommand(*m, t).command_mm;
  };
  s.forward = [m](const Vec3& q) { return q + 1e-3 * model::ToolPointError_um(*m, q); };
  s.info = {{"model", model.name}, {"formulation", model::DescribeModel(model)}};
  return s;
}

GridSource TrackerLinesGridSource(const model::TrackerData& data,
                                  const model::TrackerModel& model,
                                  TrackerMethod method,
                                  bool appendix_form) {
  GridSource s;
  for (int a = 0; a < 3; ++a) {
    const std::size_t i = static_cast<std::size_t>(a);
    s.min_mm[i] = 0;
    s.max_mm[i] = data.lines[i].back().q_mm;
    s.natural_spacing_mm[i] = model.step_mm(a);
  }
  const auto tm = std::make_shared<const model::TrackerModel>(model);
  std::string name;
  switch (method) {
    case TrackerMethod::kStatic:
      s.inverse = [tm](const Vec3& t) { return CommandOf(tm->Static(t)); };
      s.forward = [tm](const Vec3& q) { return tm->StaticPosition_mm(q); };
      name = "static";
      break;
    case TrackerMethod::kInterval:
      s.inverse = [tm](const Vec3& t) { return CommandOf(tm->Interval(t)); };
      name = "interval";
      break;
    case TrackerMethod::kQuasiDifferential:
      if (appendix_form) {
        s.inverse = [tm](const Vec3& t) { return CommandOf(tm->QuasiDifferential(t)); };
        name = "quasi-differential (Appendix Г form)";
      } else {
        s.inverse = [tm](const Vec3& t) -> Expected<Vec3> {
          return tm->ExactInverse(t).command_mm;
        };
        s.forward = [tm](const Vec3& q) { return tm->Position_mm(q); };
        name = "quasi-differential (exact inverse)";
      }
      break;
  }
  s.info = {{"data", data.name},
            {"method", name},
            {"cosines", CosineName(model.options().cosines)},
            {"origin", model.options().origin == model::OriginSource::kMeasured ? "measured"
                                                                                : "extrapolated"}};
  return s;
}

GridSource TrackerLatticeGridSource(const model::TrackerLattice& lattice) {
  GridSource s;
  const model::GridAxes& g = lattice.data().lattice;
  for (std::size_t a = 0; a < 3; ++a) {
    s.min_mm[a] = g[a].origin_mm;
    s.max_mm[a] = g[a].end_mm();
    s.natural_spacing_mm[a] = g[a].spacing_mm;
  }
  const auto tl = std::make_shared<const model::TrackerLattice>(lattice);
  s.inverse = [tl](const Vec3& t) -> Expected<Vec3> { return tl->ExactInverse(t).command_mm; };
  s.forward = [tl](const Vec3& q) { return tl->Position_mm(q); };
  s.info = {{"data", lattice.data().name},
            {"method", "lattice (quasi-differential without separability, exact inverse)"}};
  return s;
}

GridSource TrackerLatticeThroughGridSource(const model::TrackerLattice& lattice,
                                           const model::CorrectionGrid& in_force) {
  GridSource s = TrackerLatticeGridSource(lattice);
  const auto tl = std::make_shared<const model::TrackerLattice>(lattice);
  const auto g = std::make_shared<const model::CorrectionGrid>(in_force);
  s.inverse = [tl, g](const Vec3& t) -> Expected<Vec3> {
    const Vec3 u = tl->ExactInverse(t).command_mm;
    return u + g->Interpolate(u);
  };
  s.forward = [tl, g](const Vec3& q) {
    // v + in_force(v) = q: the grid's slope is ~1e-3, so the iteration contracts at once.
    Vec3 v = q;
    for (int i = 0; i < 50; ++i) {
      const Vec3 next = q - g->Interpolate(v);
      const double step = model::MaxAbs(next - v);
      v = next;
      if (step < 1e-12) break;
    }
    return tl->Position_mm(v);
  };
  s.info["method"] =
      "lattice measured through a table in force (quasi-differential without "
      "separability, exact inverse)";
  return s;
}

Expected<GridSource> KmtppGridSource(const std::array<model::AxisErrorTable, 3>& tables,
                                     const model::KmtppCalibration& calibration,
                                     const model::KmtppOptions& options) {
  GridSource s;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!(tables[a].uniform_spacing_mm() > 0)) {
      return Fail(Error::kInvalidArgument,
                  std::string("КМТПП needs equally spaced tables; axis ") + "XYZ"[a] + " is not");
    }
    s.min_mm[a] = tables[a].min_mm();
    s.max_mm[a] = tables[a].max_mm();
    s.natural_spacing_mm[a] = tables[a].uniform_spacing_mm();
  }
  s.inverse = [tables, calibration, options](const Vec3& t) {
    return CommandOf(model::Kmtpp(tables, calibration, options, t));
  };
  s.info = {
      {"law", "K=" + std::to_string(options.gain) + " l=" + std::to_string(options.step)},
      {"final_step", options.final_step == model::KmtppFinalStep::kTracedPoint
                         ? "traced point"
                         : "grid node (printed)"},
      {"sum", options.sum_form == model::KmtppSumForm::kMatrix ? "matrix (4.9)" : "listing (dot)"},
  };
  return s;
}

}  // namespace volcomp::builders
