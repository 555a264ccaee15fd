// What a GRID3 build needs from its data: the inverse map, the forward map when the data define
// one (every node is verified against it), the data's extent and natural spacing, and the INFO
// entries that name the source. One function per source, shared by `volcomp build
// model|tracker|kmtpp` and the simulator's demo, so both build from the same maps.
//   ModelGridSource          the 21-parameter model (or the dissertation's formulation)
//   TrackerLinesGridSource   laser-tracker axis lines by the static, interval or quasi-
//                            differential method (model/tracker.hpp)
//   TrackerLatticeGridSource laser-tracker readings at every node of a lattice
//                            (model/tracker_lattice.hpp)
//   KmtppGridSource          КМТПП on parametric tables (model/kmtpp.hpp)
// The maps hold copies of their data: a GridSource outlives the objects it was made from.
#pragma once

#include <array>
#include <map>
#include <string>

#include "volcomp/builders/grid.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/kmtpp.hpp"
#include "volcomp/model/lattice.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/model/tracker_lattice.hpp"

namespace volcomp::builders {

struct GridSource {
  InverseMap inverse;
  ForwardMap forward;  // empty: the source has no forward map to verify the inverse against
  std::array<double, 3> min_mm = {0, 0, 0};  // the data's extent (default --range)
  std::array<double, 3> max_mm = {0, 0, 0};
  std::array<double, 3> natural_spacing_mm = {10, 10, 10};  // table rows / measurement step
  std::map<std::string, std::string> info;                  // names the source (no "builder")

  const ForwardMap* forward_or_null() const { return forward ? &forward : nullptr; }
};

/// The model's inverse (SolveCommand) and forward map (ToolPointError_um) over its tables'
/// extent; the natural spacing is each table's row spacing (its smallest gap when irregular).
/// INFO: model, formulation. Precondition: model::ValidateModel(model) passes.
GridSource ModelGridSource(const model::Model& model);

enum class TrackerMethod { kStatic, kInterval, kQuasiDifferential };

/// The tracker lines' method: static (affine, verified), interval (no forward map: it jumps at
/// cell borders), quasi-differential (exact inverse of its forward model, verified; or the
/// Appendix Г form with `appendix_form`, unverified) of `model`, made from `data`. Extent 0 to
/// each line's last node.
/// INFO: data, method, cosines, origin.
GridSource TrackerLinesGridSource(const model::TrackerData& data,
                                  const model::TrackerModel& model,
                                  TrackerMethod method,
                                  bool appendix_form);

/// The lattice's exact inverse, verified against its trilinear forward map, over the lattice;
/// natural spacing = the lattice's. INFO: data, method.
GridSource TrackerLatticeGridSource(const model::TrackerLattice& lattice);

/// A lattice measured while the board applied the GRID3 `in_force` (mm; image_grid.hpp): its
/// commands are the board's inputs, so the new grid sends, for a target T, what the board sent for
/// the input u that reached T: c(T) = u + in_force(u) − T with u the lattice's exact inverse at T.
/// Verified against the forward map q ↦ lattice(v), v + in_force(v) = q. Over the lattice; INFO:
/// data, method. The table in force's other sections (AXIS1D) are assumed to stay in force.
GridSource TrackerLatticeThroughGridSource(const model::TrackerLattice& lattice,
                                           const model::CorrectionGrid& in_force);

/// КМТПП's command for each target (no forward map: the method defines none) over the tables'
/// extent; the natural spacing is the tables' row spacing. kInvalidArgument naming the axis when
/// a table is not equally spaced. INFO: law, final_step, sum.
Expected<GridSource> KmtppGridSource(const std::array<model::AxisErrorTable, 3>& tables,
                                     const model::KmtppCalibration& calibration,
                                     const model::KmtppOptions& options);

}  // namespace volcomp::builders
