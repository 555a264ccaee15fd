// A GRID3 image from a grid source (see grid_image.hpp).
#include "volcomp/builders/grid_image.hpp"

#include <utility>

#include "volcomp/builders/image_glue.hpp"

namespace volcomp::builders {

Expected<GridImage> BuildGridImage(const GridBuildOptions& options,
                                   image::ImageRequest request,
                                   const GridSource& source) {
  GridImage out;
  VOLCOMP_TRY_ASSIGN(out.grid, BuildGridSection(options, request.axes, source));
  request.grid = out.grid.section;
  for (const auto& [k, v] : out.grid.info) request.info.emplace(k, v);
  const bool float32 = request.element == table::ElementType::kFloat32;
  if (!request.frac_bits && !float32) {
    VOLCOMP_TRY_ASSIGN(request.frac_bits, image::ChooseFracBits(request));
  }
  out.frac_bits = float32 ? 0 : *request.frac_bits;
  VOLCOMP_TRY_ASSIGN(out.bytes, image::BuildImage(request));
  for (std::size_t a = 0; a < 3; ++a) {
    out.lsb_um[a] = float32 ? 0.0 : LsbUm(request.axes[a], out.frac_bits);
  }
  out.request = std::move(request);
  return out;
}

}  // namespace volcomp::builders
