// A regular 3-D lattice in mm and a field of vectors at its nodes, read between the nodes by
// trilinear interpolation clamped to the lattice, as the board reads a GRID3.
// Lengths in mm; node order x fastest.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

struct GridAxis {
  double origin_mm = 0.0;
  double spacing_mm = 1.0;
  uint32_t nodes = 2;
  double end_mm() const { return origin_mm + spacing_mm * (nodes - 1); }
};
using GridAxes = std::array<GridAxis, 3>;

/// Corrections at the nodes of a lattice, x fastest: index (k·ny + j)·nx + i.
struct CorrectionGrid {
  GridAxes axes;
  std::vector<Vec3> correction_mm;

  std::size_t Index(uint32_t i, uint32_t j, uint32_t k) const {
    return (static_cast<std::size_t>(k) * axes[1].nodes + j) * axes[0].nodes + i;
  }
  Vec3 NodePosition(uint32_t i, uint32_t j, uint32_t k) const;
  /// Trilinear interpolation of the corrections, clamped to the lattice (as the board does).
  Vec3 Interpolate(const Vec3& p_mm) const;
};

}  // namespace volcomp::model
