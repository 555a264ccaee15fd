// From an inverse map to a GRID3 of corrections: lattice, sampling, trilinear prediction of the
// interpolation error between nodes, spacing choice and the correction bound.
//
// The grid holds, at each node T (a target, i.e. the nominal command the CNC sends), the correction
// c(T) = q(T) − T where q(T) is the command that lands the tool on T. The board adds the trilinear
// interpolation of c to every command, so the residual error between nodes is
// |trilinear(c)(T) − c(T)|, which PredictInterpolationError samples densely.
// Lengths in mm, errors reported in µm.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
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

/// The command for a target (the inverse map), mm.
using InverseMap = std::function<Vec3(const Vec3& target_mm)>;
/// The tool position reached for a command (the forward map), mm; used to verify an inverse.
using ForwardMap = std::function<Vec3(const Vec3& command_mm)>;

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

struct GridSampleStats {
  double max_residual_um = 0.0;    // worst |forward(q) − T| over the nodes (0 without a check)
  double max_correction_um = 0.0;  // largest |c| component
  Vec3 max_correction_at_mm;
};

/// Evaluates the inverse at every node. With a forward map, also verifies each node.
CorrectionGrid SampleGrid(const GridAxes& spec,
                          const InverseMap& inverse,
                          const ForwardMap* forward = nullptr,
                          GridSampleStats* stats = nullptr);

struct InterpolationReport {
  double max_um = 0.0;  // largest |trilinear − exact| (vector norm) over the samples
  double rms_um = 0.0;
  Vec3 worst_at_mm;
  std::size_t samples = 0;
};

/// Samples every cell (or `max_cells` of them, chosen evenly at random with a fixed seed) at its
/// centre and `points_per_cell` random points and compares the trilinear value with the exact
/// correction inverse(T) − T.
InterpolationReport PredictInterpolationError(const CorrectionGrid& grid,
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
  CorrectionGrid grid;
  GridSampleStats stats;
  InterpolationReport interpolation;
  /// Every spacing tried by the automatic choice: (spacing per axis, predicted max µm).
  std::vector<std::pair<std::array<double, 3>, double>> tried;
};

/// Lays out the lattice for a spacing: origin = min, nodes to cover max, everything in whole
/// steps; throws std::invalid_argument with the reason (e.g. spacing not a whole number of steps).
GridAxes MakeGridAxes(const GridBuildOptions& options, const std::array<double, 3>& spacing_mm);

/// Why BuildCorrectionGrid refused the data.
enum class GridRefusal : uint8_t {
  kCorrectionBound,      // a node's correction exceeds max_correction_um
  kInverseResidual,      // an inverse misses its target by more than max_residual_um
  kInterpolationTarget,  // no spacing within the node limits reaches max_interp_error_um
};

/// BuildCorrectionGrid's refusal: what() says what and where, kind() which check refused.
class GridBuildError : public std::runtime_error {
 public:
  GridBuildError(GridRefusal kind, const std::string& what)
      : std::runtime_error(what), kind_(kind) {}
  GridRefusal kind() const { return kind_; }

 private:
  GridRefusal kind_;
};

/// Builds the grid: explicit spacing, or the automatic choice, then the checks. Throws
/// GridBuildError when a node's correction exceeds the bound, an inverse misses its target by
/// more than max_residual_um, or no spacing within the node limits reaches max_interp_error_um;
/// std::invalid_argument (MakeGridAxes) for a lattice that cannot be laid out.
GridBuildResult BuildCorrectionGrid(const GridBuildOptions& options,
                                    const InverseMap& inverse,
                                    const ForwardMap* forward = nullptr);

}  // namespace volcomp::model
