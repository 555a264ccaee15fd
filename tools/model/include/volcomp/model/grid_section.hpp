// From a grid source to the GRID3 section of an image: the building blocks `volcomp build
// model|tracker` use (BuildCorrectionGrid with its checks, ToGridCorrections), without writing
// files or printing, for callers that assemble an image themselves (the simulator's demo puts a
// GRID3 and AXIS1D tables in one image).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/grid.hpp"
#include "volcomp/model/grid_source.hpp"

namespace volcomp::model {

struct GridSection {
  GridBuildResult build;           // lattice, corrections, node checks, predicted interpolation
  image::GridCorrections section;  // in steps of `axes`
  std::map<std::string, std::string> info;  // the source's entries + lattice_mm,
                                            // predicted_interp_error_um
};

/// Builds the grid of `source` with `options` (spacing, range, bounds; options.step_mm must be
/// the axes' step lengths) and converts it for image axes `axes` (X, Y, Z). Throws what
/// BuildCorrectionGrid and ToGridCorrections throw (bound exceeded, inverse residual, spacing not
/// in whole steps).
GridSection BuildGridSection(const GridBuildOptions& options,
                             const std::vector<image::AxisDef>& axes,
                             const GridSource& source);

}  // namespace volcomp::model
