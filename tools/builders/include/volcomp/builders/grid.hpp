// From an inverse map to a GRID3 of corrections: lattice, sampling, trilinear prediction of the
// interpolation error between nodes, spacing choice and the correction bound.
//
// The grid holds, at each node T (a target, i.e. the nominal command the CNC sends), the correction
// c(T) = q(T) − T where q(T) is the command that lands the tool on T. The board adds the trilinear
// interpolation of c to every command, so the residual error between nodes is
// |trilinear(c)(T) − c(T)|, which PredictInterpolationError samples densely.
// Lengths in mm, errors reported in µm. An inverse map may fail (a singular matrix in a method);
// its failure ends the build and is returned as it is.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/lattice.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::builders {

/// The command for a target (the inverse map), mm.
using InverseMap = std::function<Expected<model::Vec3>(const model::Vec3& target_mm)>;
/// The tool position reached for a command (the forward map), mm; used to verify an inverse.
using ForwardMap = std::function<model::Vec3(const model::Vec3& command_mm)>;

struct GridSampleStats {
  double max_residual_um = 0.0;    // worst |forward(q) − T| over the nodes (0 without a check)
  double max_correction_um = 0.0;  // largest |c| component
  model::Vec3 max_correction_at_mm;
};

/// Evaluates the inverse at every node. With a forward map, also verifies each node.
Expected<model::CorrectionGrid> SampleGrid(const model::GridAxes& spec,
                                           const InverseMap& inverse,
                                           const ForwardMap* forward = nullptr,
                                           GridSampleStats* stats = nullptr);

struct InterpolationReport {
  double max_um = 0.0;  // largest |trilinear − exact| (vector norm) over the samples
  double rms_um = 0.0;
  model::Vec3 worst_at_mm;
  std::size_t samples = 0;
};

/// Samples every cell (or `max_cells` of them, chosen evenly at random with a fixed seed) at its
/// centre and `points_per_cell` random points and compares the trilinear value with the exact
/// correction inverse(T) − T.
Expected<InterpolationReport> PredictInterpolationError(const model::CorrectionGrid& grid,
                                                        const InverseMap& inverse,
                                                        std::size_t max_cells = 20000,
                                                        int points_per_cell = 4,
                                                        uint64_t seed = 1);

/// What a builder needs to lay out and check a grid.
struct GridBuildOptions {
  std::array<double, 3> min_mm = {0, 0, 0};
  std::array<double, 3> max_mm = {0, 0, 0};
  /// Explicit spacing per axis (mm); 0 = not given.
  std::array<double, 3> spacing_mm = {0, 0, 0};
  /// With no explicit spacing: the coarsest spacing whose predicted interpolation error is below
  /// this (µm); 0 = use natural_spacing_mm.
  double max_interp_error_um = 0.0;
  /// The data's own spacing (table or measurement step), the start of the spacing search.
  std::array<double, 3> natural_spacing_mm = {10, 10, 10};
  /// Length of one step of each axis (mm); spacing and origin must be whole steps.
  std::array<double, 3> step_mm = {0.001, 0.001, 0.001};
  double max_correction_um = 1000.0;  // refuse anything larger
  double max_residual_um = 0.01;      // inverse must land within this at every node
  std::size_t max_nodes = 1u << 20;
  uint32_t max_nodes_per_axis = 1024;
};

struct GridBuildResult {
  model::CorrectionGrid grid;
  GridSampleStats stats;
  InterpolationReport interpolation;
  /// Every spacing tried by the automatic choice: (spacing per axis, predicted max µm).
  std::vector<std::pair<std::array<double, 3>, double>> tried;
};

/// Lays out the lattice for a spacing: origin = min, nodes to cover max, everything in whole
/// steps; kInvalidArgument with the reason (e.g. spacing not a whole number of steps).
Expected<model::GridAxes> MakeGridAxes(const GridBuildOptions& options,
                                       const std::array<double, 3>& spacing_mm);

/// Builds the grid: explicit spacing, or the automatic choice, then the checks. Failures:
///   kInvalidArgument  the lattice cannot be laid out (MakeGridAxes);
///   kOutOfRange       a node's correction exceeds max_correction_um (the bound);
///   kInputInvalid     an inverse misses its target by more than max_residual_um, or no spacing
///                     within the node limits reaches max_interp_error_um;
/// and the inverse map's own failures.
Expected<GridBuildResult> BuildCorrectionGrid(const GridBuildOptions& options,
                                              const InverseMap& inverse,
                                              const ForwardMap* forward = nullptr);

}  // namespace volcomp::builders
