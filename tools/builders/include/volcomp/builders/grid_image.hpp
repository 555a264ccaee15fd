// A GRID3 image from a grid source, as `volcomp build model|tracker|kmtpp` write it: the grid
// section (grid_section.hpp) in the image request, its INFO entries added to the request's (an
// entry the request already has stays), the fraction bits chosen when not given, the image built
// and validated. Writing the file is the caller's.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "volcomp/builders/grid.hpp"
#include "volcomp/builders/grid_section.hpp"
#include "volcomp/builders/grid_source.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"

namespace volcomp::builders {

struct GridImage {
  GridSection grid;
  image::ImageRequest request;               // as built: grid, INFO and fraction bits filled in
  std::vector<uint8_t> bytes;                // the validated image
  uint8_t frac_bits = 0;                     // 0 for float32
  std::array<double, 3> lsb_um = {0, 0, 0};  // element LSB per axis; 0 for float32
};

/// `request` holds the axes X, Y, Z and the element, fraction bits, table id and INFO the caller
/// wants. Fails as BuildGridSection does, or (kInputInvalid) as image::BuildImage does.
Expected<GridImage> BuildGridImage(const GridBuildOptions& options,
                                   image::ImageRequest request,
                                   const GridSource& source);

}  // namespace volcomp::builders
