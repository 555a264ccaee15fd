// Compensation tables from the demo's measurements, built with the entry points of the PC tool's
// builders (tools/model), never a copy: the measured 21-parameter model (`volcomp build model`;
// its squareness is in the straightness slopes), AXIS1D forward and reverse tables from ISO 230-2
// runs (`build axis --reverse tables`), a tracker lattice through the table in force (`build
// tracker --lattice --through`); AssembleTable puts them in one image the firmware's parser
// validates. A builder's refusal comes back as a failure with the builder's reason.
// Lengths mm, corrections µm.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/builders/axis_section.hpp"
#include "volcomp/builders/grid_section.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/tracker_lattice.hpp"
#include "volcomp/sim/measurements.hpp"

namespace volcomp::sim {

/// The measured 21-parameter model: the runs' six error motions (zero at the reference point,
/// where the three lines meet) as its axis tables, squareness 0 (it is in the straightness
/// slopes), `chain`; physical formulation, exact rotations, tool offset 0. kInvalidArgument when
/// the runs are not X, Y, Z in order or the model is refused.
Expected<model::Model> ModelFromParametric(const std::array<ParametricResult, 3>& runs,
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
/// added to the sections' own entries. With both, each goes into an image of its own (its own
/// fraction bits) and the two are joined by image::JoinImages, as `volcomp build image --grid
/// --axis` does; frac_bits and lsb_um are then the GRID3's.
Expected<TableBuildResult> AssembleTable(const std::optional<builders::GridSection>& grid,
                                         const std::vector<builders::AxisSection>& axis_tables,
                                         const std::array<double, 3>& step_mm,
                                         uint32_t table_id,
                                         const std::map<std::string, std::string>& info);

/// The GRID3 section of the measured model on `lattice` (LatticeOptions: extent, node spacing and
/// step size; ModelGridSource, BuildGridSection).
Expected<builders::GridSection> BuildModelGridSection(const model::Model& measured,
                                                      const builders::GridBuildOptions& lattice);

/// The GRID3 image of the measured model (BuildModelGridSection, then AssembleTable).
Expected<TableBuildResult> BuildTableImage(const model::Model& measured,
                                           const builders::GridBuildOptions& lattice,
                                           uint32_t table_id);

/// The AXIS1D section of `axis` (0..2) from mean deviations per target: the forward table at
/// `spacing_mm` and one backlash value, the mean reversal over the nodes (`volcomp build axis
/// --reverse backlash`, BuildAxisSection). The lost motion of a nut and its coupling is one value
/// along the axis; its reversal measured at every node scatters by the runs' repeatability
/// (about ±0.5 um per node with 5 runs on the worn machine), which per-node reverse tables would
/// carry into the table and the mean of the nodes does not.
Expected<builders::AxisSection> BuildAxisTable(const model::PositioningData& deviations,
                                               int axis,
                                               double spacing_mm,
                                               const std::array<double, 3>& step_mm);

/// The GRID3 section from tracker readings at the nodes of a lattice, measured through the table
/// in force (`in_force`, its image), composed with that table's GRID3
/// (`volcomp build tracker --lattice --through`: GridOfImage, TrackerLatticeThroughGridSource,
/// BuildGridSection), on `grid` (LatticeOptions).
Expected<builders::GridSection> BuildTrackerLatticeGridSection(
    const model::TrackerLatticeData& readings,
    const std::vector<uint8_t>& in_force,
    const builders::GridBuildOptions& grid);

/// The measured model as files `volcomp build model --model DIR/measured.conf` reads:
/// measured.conf and measured_x.csv, measured_y.csv, measured_z.csv in `dir` (kIoError when a
/// file cannot be written).
Outcome WriteModelFiles(const model::Model& measured, const std::string& dir);

}  // namespace volcomp::sim
