// Tracker lattices sampled from machines given in closed form (tests of the lattice model and of
// the builders on it).
#pragma once

#include <cstdint>
#include <functional>

#include "volcomp/model/tracker_lattice.hpp"

namespace volcomp::testing {

/// Readings of `machine` (command → tool position, mm) at every node of `lattice` (x fastest).
inline model::TrackerLatticeData SampleLattice(
    const std::function<model::Vec3(const model::Vec3&)>& machine, const model::GridAxes& lattice) {
  model::TrackerLatticeData d;
  d.name = "sampled";
  d.lattice = lattice;
  for (uint32_t k = 0; k < lattice[2].nodes; ++k) {
    for (uint32_t j = 0; j < lattice[1].nodes; ++j) {
      for (uint32_t i = 0; i < lattice[0].nodes; ++i) {
        d.position_mm.push_back(machine({lattice[0].origin_mm + i * lattice[0].spacing_mm,
                                         lattice[1].origin_mm + j * lattice[1].spacing_mm,
                                         lattice[2].origin_mm + k * lattice[2].spacing_mm}));
      }
    }
  }
  return d;
}

/// 0..200 x −20..100 x 0..100 mm every 40, 30, 50 mm.
inline const model::GridAxes kSampleLattice = {
    model::GridAxis{0, 40, 6}, model::GridAxis{-20, 30, 5}, model::GridAxis{0, 50, 3}};

}  // namespace volcomp::testing
