// Trilinear reading of a vector field on a lattice (see lattice.hpp).
#include "volcomp/model/lattice.hpp"

namespace volcomp::model {

Vec3 CorrectionGrid::NodePosition(uint32_t i, uint32_t j, uint32_t k) const {
  return {axes[0].origin_mm + axes[0].spacing_mm * i, axes[1].origin_mm + axes[1].spacing_mm * j,
          axes[2].origin_mm + axes[2].spacing_mm * k};
}

Vec3 CorrectionGrid::Interpolate(const Vec3& p_mm) const {
  uint32_t idx[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    const GridAxis& g = axes[static_cast<std::size_t>(a)];
    double f = (p_mm[a] - g.origin_mm) / g.spacing_mm;
    const double last = static_cast<double>(g.nodes - 1);
    if (!(f > 0.0)) f = 0.0;
    if (f > last) f = last;
    uint32_t i = static_cast<uint32_t>(f);
    if (i > g.nodes - 2) i = g.nodes - 2;
    idx[a] = i;
    t[a] = f - i;
  }
  Vec3 out;
  for (int dk = 0; dk < 2; ++dk) {
    for (int dj = 0; dj < 2; ++dj) {
      for (int di = 0; di < 2; ++di) {
        const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
        if (w == 0.0) continue;
        out += w * correction_mm[Index(idx[0] + static_cast<uint32_t>(di),
                                       idx[1] + static_cast<uint32_t>(dj),
                                       idx[2] + static_cast<uint32_t>(dk))];
      }
    }
  }
  return out;
}

}  // namespace volcomp::model
