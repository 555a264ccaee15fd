// A virtual telescoping ballbar (ISO 230-4 circular test): a length sensor between a pivot on the
// table and the tool point, reading the machine's actual tool point (its own kinematics at the
// carriages' positions) less the work offset, with its own noise and resolution (default: 0.1 um
// resolution and noise, a QC20-W class sensor). Lengths mm, readings um. Thread-safety: none.
#pragma once

#include <cstdint>

#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/instruments.hpp"
#include "volcomp/sim/machine.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim {

struct BallbarOptions {
  ChannelErrors length_um = {0.1, 1, 0.0, 0.1};
};

class Ballbar {
 public:
  /// `pivot_mm`: the centre ball's position in the machine frame (the circle's programmed centre,
  /// set by touching it off).
  Ballbar(const Machine* machine,
          const model::Vec3& pivot_mm,
          const BallbarOptions& options,
          uint64_t seed);

  /// The bar's length minus `nominal_mm` (um) with the axes at `q_mm` and the tool point shifted
  /// by -`work_offset_mm`.
  double Deviation_um(const model::Vec3& q_mm,
                      const model::Vec3& work_offset_mm,
                      double nominal_mm);
  /// The same without the sensor's errors.
  double TrueDeviation_um(const model::Vec3& q_mm,
                          const model::Vec3& work_offset_mm,
                          double nominal_mm) const;

 private:
  const Machine* machine_;
  model::Vec3 pivot_mm_;
  BallbarOptions options_;
  Random rng_;
};

}  // namespace volcomp::sim
