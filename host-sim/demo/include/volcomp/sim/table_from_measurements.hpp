// The compensation table from the parametric measurements, built with the entry points of
// `volcomp build model` (tools/model grid_source.hpp, grid_section.hpp):
//   1. the measured six error motions of X, Y and Z (zeroed at the reference point, where the three
//      measuring lines meet) become the axis tables of a 21-parameter model; the squareness is in
//      the straightness slopes (the beam was aligned with the nominal axes), so the model's
//      squareness entries are 0; the kinematic chain is the machine's (the integrator knows it);
//   2. ModelGridSource + BuildGridSection invert that model at every node of a lattice over the
//      measured travel (command that lands the tool on the node, residual <= 0.01 µm) and predict
//      the interpolation error between nodes;
//   3. tools/image writes the GRID3 image (int16, fraction bits chosen to fit), validated with the
//      firmware's parser.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "volcomp/model/grid.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/sim/measurements.hpp"
#include "volcomp/sim/sim_status.hpp"

namespace volcomp::sim {

/// The measured 21-parameter model (physical formulation, exact rotations, tool offset 0).
/// kInvalidArgument when the runs are not X, Y, Z in order.
SimResult<model::Model> ModelFromParametric(const std::array<ParametricResult, 3>& runs,
                                            const model::KinematicChain& chain);

struct TableBuildResult {
  model::GridBuildResult grid;
  std::vector<uint8_t> image;
  uint32_t crc32 = 0;
  uint8_t frac_bits = 0;
  double lsb_um = 0;
  std::map<std::string, std::string> info;
};

/// Builds the GRID3 image over [lo, hi] (mm) with the given node spacing (mm) for axes of
/// `step_mm` per step. Throws std::runtime_error / tools::InputError with the reason.
TableBuildResult BuildTableImage(const model::Model& measured,
                                 const std::array<double, 3>& lo_mm,
                                 const std::array<double, 3>& hi_mm,
                                 const std::array<double, 3>& spacing_mm,
                                 const std::array<double, 3>& step_mm,
                                 uint32_t table_id);

/// The measured model as files `volcomp build model --model DIR/measured.conf` reads:
/// measured.conf and measured_x.csv, measured_y.csv, measured_z.csv in `dir` (kIoError when a
/// file cannot be written).
SimStatus WriteModelFiles(const model::Model& measured, const std::string& dir);

}  // namespace volcomp::sim
