// The GRID3 of an image in mm (see image_grid.hpp).
#include "volcomp/builders/image_grid.hpp"

#include <cmath>

#include "volcomp/base/byte_order.hpp"

namespace volcomp::builders {

Expected<model::CorrectionGrid> GridOfImage(const image::LoadedImage& image,
                                            const std::string& source) {
  const table::TableView& v = image.view();
  const table::Grid3View& g = v.grid;
  if (!g.present) return Fail(Error::kInputInvalid, source + ": the image has no GRID3");
  model::CorrectionGrid out;
  double step_mm[3];
  for (int d = 0; d < 3; ++d) {
    const table::AxisInfo& axis = v.axes[g.axis[d]];
    if (g.axis[d] != d || axis.kind != table::AxisKind::kLinear) {
      return Fail(Error::kInputInvalid, source + ": the GRID3 must map X, Y, Z (linear) in order");
    }
    step_mm[d] = static_cast<double>(axis.resolution_e9) * 1e-9;
    model::GridAxis& a = out.axes[static_cast<std::size_t>(d)];
    a.nodes = g.dim[d].nodes;
    a.origin_mm = g.dim[d].origin_steps * step_mm[d];
    a.spacing_mm = g.dim[d].spacing_steps * step_mm[d];
  }
  const std::size_t n = static_cast<std::size_t>(g.dim[0].nodes) * g.dim[1].nodes * g.dim[2].nodes;
  const double lsb = std::ldexp(1.0, -static_cast<int>(g.frac_bits));
  out.correction_mm.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const std::size_t e = 3 * i + static_cast<std::size_t>(c);
      double steps = 0;
      switch (g.type) {
        case table::ElementType::kInt16:
          steps = static_cast<int16_t>(LoadLe16(g.data + 2 * e)) * lsb;
          break;
        case table::ElementType::kInt32:
          steps = LoadLeI32(g.data + 4 * e) * lsb;
          break;
        case table::ElementType::kFloat32:
          steps = LoadLeF32(g.data + 4 * e);
          break;
      }
      out.correction_mm[i][c] = steps * step_mm[c];
    }
  }
  return out;
}

}  // namespace volcomp::builders
