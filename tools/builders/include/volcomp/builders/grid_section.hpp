// From a grid source to the GRID3 section of an image: the building blocks `volcomp build
// model|tracker|kmtpp` use (BuildCorrectionGrid with its checks, ToGridCorrections), without
// writing files, for callers that assemble an image themselves (the simulator's demo puts a GRID3
// and AXIS1D tables in one image); grid_image.hpp makes the whole image.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "volcomp/builders/grid.hpp"
#include "volcomp/builders/grid_source.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::builders {

struct GridSection {
  GridBuildResult build;           // lattice, corrections, node checks, predicted interpolation
  image::GridCorrections section;  // in steps of `axes`
  std::map<std::string, std::string> info;  // the source's entries + lattice_mm,
                                            // predicted_interp_error_um
};

/// Builds the grid of `source` with `options` (spacing, range, bounds; options.step_mm must be
/// the axes' step lengths) and converts it for image axes `axes` (X, Y, Z). Fails as
/// BuildCorrectionGrid does, or kInputInvalid when the lattice is not in whole steps of `axes`.
Expected<GridSection> BuildGridSection(const GridBuildOptions& options,
                                       const std::vector<image::AxisDef>& axes,
                                       const GridSource& source);

}  // namespace volcomp::builders
