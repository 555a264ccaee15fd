// Laser-tracker lattice: trilinear forward map and its inverse (see tracker_lattice.hpp).
#include "volcomp/model/tracker_lattice.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace volcomp::model {

Expected<TrackerLattice> TrackerLattice::Create(TrackerLatticeData data) {
  std::size_t total = 1;
  for (const GridAxis& a : data.lattice) {
    if (a.nodes < 2 || !(a.spacing_mm > 0) || !std::isfinite(a.origin_mm)) {
      return Fail(Error::kInvalidArgument,
                  "tracker lattice: every axis needs >= 2 nodes at a positive spacing");
    }
    total *= a.nodes;
  }
  if (data.position_mm.size() != total) {
    return Fail(Error::kInvalidArgument,
                "tracker lattice: " + std::to_string(data.position_mm.size()) + " readings for " +
                    std::to_string(total) + " nodes");
  }
  for (const Vec3& p : data.position_mm) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return Fail(Error::kInvalidArgument, "tracker lattice: a reading is not finite");
    }
  }
  return TrackerLattice(std::move(data));
}

Vec3 TrackerLattice::Position_mm(const Vec3& command_mm) const {
  const GridAxes& g = data_.lattice;
  uint32_t cell[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const GridAxis& ax = g[static_cast<std::size_t>(a)];
    const double u = (command_mm[a] - ax.origin_mm) / ax.spacing_mm;
    const double c = std::fmin(std::fmax(std::floor(u), 0.0), static_cast<double>(ax.nodes - 2));
    cell[a] = static_cast<uint32_t>(c);
    f[a] = u - c;  // outside [0, 1] beyond the lattice: the boundary cell extrapolates
  }
  Vec3 p;
  for (uint32_t corner = 0; corner < 8; ++corner) {
    const uint32_t di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double w = (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]);
    const std::size_t n =
        (static_cast<std::size_t>(cell[2] + dk) * g[1].nodes + cell[1] + dj) * g[0].nodes +
        cell[0] + di;
    p += w * data_.position_mm[n];
  }
  return p;
}

InverseSolution TrackerLattice::ExactInverse(const Vec3& target_mm, double tolerance_mm) const {
  const auto error_mm = [this](const Vec3& q) { return Position_mm(q) - q; };
  return InvertError(error_mm, target_mm, tolerance_mm);
}

}  // namespace volcomp::model
