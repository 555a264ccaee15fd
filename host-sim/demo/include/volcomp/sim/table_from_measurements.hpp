// Compensation tables from the demo's measurements, built with the entry points of the PC tool's
// builders (tools/builders grid_source.hpp, grid_section.hpp, axis_section.hpp), never a copy:
//   * 21-parameter: the measured six error motions of X, Y and Z (zeroed at the reference point,
//     where the three measuring lines meet) become the axis tables of a model; the squareness is
//     in the straightness slopes (the optics were aligned with the nominal axes), so the model's
//     squareness entries are 0; the kinematic chain is the machine's (the integrator knows it).
//     ModelGridSource + BuildGridSection invert it at every node (`volcomp build model`).
//   * Tracker lattice: readings at every node of a lattice, TrackerLatticeGridSource +
//     BuildGridSection (`volcomp build tracker --lattice`).
//   * AXIS1D: the mean deviations x̄↑, x̄↓ per target of a bidirectional ISO 230-2 run, forward
//     and reverse tables, BuildAxisSection (`volcomp build axis --reverse tables`).
// AssembleTable puts a GRID3 and/or AXIS1D tables in one image (int16, fraction bits chosen to
// fit), which the firmware's parser validates.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/builders/axis_section.hpp"
#include "volcomp/builders/grid_section.hpp"
#include "volcomp/model/positioning.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/tracker_lattice.hpp"
#include "volcomp/sim/measurements.hpp"
#include "volcomp/sim/sim_status.hpp"

namespace volcomp::sim {

/// The measured 21-parameter model (physical formulation, exact rotations, tool offset 0).
/// kInvalidArgument when the runs are not X, Y, Z in order.
SimResult<model::Model> ModelFromParametric(const std::array<ParametricResult, 3>& runs,
                                            const model::KinematicChain& chain);

/// Image axes X, Y, Z (linear) of `step_mm` per step.
std::vector<image::AxisDef> ImageAxes(const std::array<double, 3>& step_mm);

/// A lattice over [lo, hi] (mm) with the given node spacing, for axes of `step_mm` per step.
builders::GridBuildOptions LatticeOptions(const std::array<double, 3>& lo_mm,
                                          const std::array<double, 3>& hi_mm,
                                          const std::array<double, 3>& spacing_mm,
                                          const std::array<double, 3>& step_mm);

/// The mean deviations per target of a bidirectional positioning run, as `build axis` reads them.
model::PositioningData MeanDeviations(const metrology::PositioningResult& run);
/// Targets measured in pairs (t − d, t + d), in order: one target t per pair with the pair's mean
/// deviations (cancels an error of period 4d). An odd last target is dropped.
model::PositioningData PairMeans(const model::PositioningData& targets);

struct TableBuildResult {
  std::optional<builders::GridSection> grid;
  std::vector<builders::AxisSection> axis_tables;  // one per axis, in axis order
  std::vector<uint8_t> image;
  uint32_t crc32 = 0;
  uint8_t frac_bits = 0;
  double lsb_um = 0;
  std::map<std::string, std::string> info;
};

/// One image from a GRID3 section and/or AXIS1D sections (axis_tables[i] is axis i). `info` is
/// added to the sections' own entries.
TableBuildResult AssembleTable(const std::optional<builders::GridSection>& grid,
                               const std::vector<builders::AxisSection>& axis_tables,
                               const std::array<double, 3>& step_mm,
                               uint32_t table_id,
                               const std::map<std::string, std::string>& info);

/// The GRID3 image of the measured model over [lo, hi] (mm) with the given node spacing (mm) for
/// axes of `step_mm` per step. Throws what BuildGridSection throws.
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
