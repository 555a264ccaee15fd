// The sources of a GRID3 build (see grid_source.hpp).
#include "volcomp/model/grid_source.hpp"

#include <algorithm>
#include <memory>

#include "volcomp/model/build_cli.hpp"

namespace volcomp::model {

GridSource ModelGridSource(const Model& model) {
  GridSource s;
  for (std::size_t a = 0; a < 3; ++a) {
    const AxisErrorTable& t = model.axes[a];
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
  const auto m = std::make_shared<const Model>(model);
  s.inverse = [m](const Vec3& t) { return SolveCommand(*m, t).command_mm; };
  s.forward = [m](const Vec3& q) { return q + 1e-3 * ToolPointError_um(*m, q); };
  s.info = {{"model", model.name}, {"formulation", cli::DescribeModel(model)}};
  return s;
}

namespace {

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

}  // namespace

GridSource TrackerLinesGridSource(const TrackerData& data,
                                  const TrackerModel& model,
                                  TrackerMethod method,
                                  bool appendix_form) {
  GridSource s;
  for (int a = 0; a < 3; ++a) {
    const std::size_t i = static_cast<std::size_t>(a);
    s.min_mm[i] = 0;
    s.max_mm[i] = data.lines[i].back().q_mm;
    s.natural_spacing_mm[i] = model.step_mm(a);
  }
  const auto tm = std::make_shared<const TrackerModel>(model);
  std::string name;
  switch (method) {
    case TrackerMethod::kStatic:
      s.inverse = [tm](const Vec3& t) { return tm->Static(t).command_mm; };
      s.forward = [tm](const Vec3& q) { return tm->StaticPosition_mm(q); };
      name = "static";
      break;
    case TrackerMethod::kInterval:
      s.inverse = [tm](const Vec3& t) { return tm->Interval(t).command_mm; };
      name = "interval";
      break;
    case TrackerMethod::kQuasiDifferential:
      if (appendix_form) {
        s.inverse = [tm](const Vec3& t) { return tm->QuasiDifferential(t).command_mm; };
        name = "quasi-differential (Appendix Г form)";
      } else {
        s.inverse = [tm](const Vec3& t) { return tm->ExactInverse(t).command_mm; };
        s.forward = [tm](const Vec3& q) { return tm->Position_mm(q); };
        name = "quasi-differential (exact inverse)";
      }
      break;
  }
  s.info = {
      {"data", data.name},
      {"method", name},
      {"cosines", CosineName(model.options().cosines)},
      {"origin", model.options().origin == OriginSource::kMeasured ? "measured" : "extrapolated"}};
  return s;
}

GridSource TrackerLatticeGridSource(const TrackerLattice& lattice) {
  GridSource s;
  const GridAxes& g = lattice.data().lattice;
  for (std::size_t a = 0; a < 3; ++a) {
    s.min_mm[a] = g[a].origin_mm;
    s.max_mm[a] = g[a].end_mm();
    s.natural_spacing_mm[a] = g[a].spacing_mm;
  }
  const auto tl = std::make_shared<const TrackerLattice>(lattice);
  s.inverse = [tl](const Vec3& t) { return tl->ExactInverse(t).command_mm; };
  s.forward = [tl](const Vec3& q) { return tl->Position_mm(q); };
  s.info = {{"data", lattice.data().name},
            {"method", "lattice (quasi-differential without separability, exact inverse)"}};
  return s;
}

GridSource TrackerLatticeThroughGridSource(const TrackerLattice& lattice,
                                           const CorrectionGrid& in_force) {
  GridSource s = TrackerLatticeGridSource(lattice);
  const auto tl = std::make_shared<const TrackerLattice>(lattice);
  const auto g = std::make_shared<const CorrectionGrid>(in_force);
  s.inverse = [tl, g](const Vec3& t) {
    const Vec3 u = tl->ExactInverse(t).command_mm;
    return u + g->Interpolate(u);
  };
  s.forward = [tl, g](const Vec3& q) {
    // v + in_force(v) = q: the grid's slope is ~1e-3, so the iteration contracts at once.
    Vec3 v = q;
    for (int i = 0; i < 50; ++i) {
      const Vec3 next = q - g->Interpolate(v);
      const double step = MaxAbs(next - v);
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

}  // namespace volcomp::model
