// GRID3 section from a grid source (see grid_section.hpp).
#include "volcomp/builders/grid_section.hpp"

#include <cstdio>

#include "volcomp/builders/image_glue.hpp"

namespace volcomp::builders {
namespace {

std::string Num(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

}  // namespace

Expected<GridSection> BuildGridSection(const GridBuildOptions& options,
                                       const std::vector<image::AxisDef>& axes,
                                       const GridSource& source) {
  GridSection s;
  VOLCOMP_TRY_ASSIGN(s.build,
                     BuildCorrectionGrid(options, source.inverse, source.forward_or_null()));
  VOLCOMP_TRY_ASSIGN(s.section, ToGridCorrections(s.build.grid, axes));
  s.info = source.info;
  const model::GridAxes& g = s.build.grid.axes;
  std::string lattice;
  for (std::size_t a = 0; a < 3; ++a) {
    if (a > 0) lattice += ",";
    lattice += Num(g[a].origin_mm) + ":" + Num(g[a].spacing_mm) + ":" + Num(g[a].end_mm());
  }
  s.info.emplace("lattice_mm", lattice);
  s.info.emplace("predicted_interp_error_um", Num(s.build.interpolation.max_um, 4));
  return s;
}

}  // namespace volcomp::builders
