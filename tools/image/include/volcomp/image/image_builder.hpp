// Hosted image building for the PC tool: corrections in steps (double) -> a validated table image.
//
// This is the layer every `volcomp build ...` command uses. It chooses the element encoding
// (fraction bits) if asked, quantises with rounding to nearest, writes the image through the
// freestanding writer in lib/ and re-validates the result with the same parser the firmware uses,
// so a returned image is always valid. Failures are kInputInvalid with a readable reason (e.g. a
// correction beyond the representable range, naming the node).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::image {

/// One machine axis as the image records it.
struct AxisDef {
  char name = 'X';                                  // one of table::kAxisNames
  table::AxisKind kind = table::AxisKind::kLinear;  // linear (mm) or rotary (degrees)
  uint32_t resolution_e9 = 1000000;                 // units per step x 1e9: pm/step or ndeg/step
  /// Millimetres (or degrees) per step.
  double units_per_step() const { return resolution_e9 * 1e-9; }
};

/// One lattice dimension in steps.
struct Lattice {
  uint32_t nodes = 2;
  int32_t origin_steps = 0;
  uint32_t spacing_steps = 1;
};

/// A GRID3: correction vectors (in steps of the component's axis) at lattice nodes.
struct GridCorrections {
  std::array<uint8_t, 3> axis = {0, 1, 2};  // axis index (into ImageRequest::axes) of dim/component
  std::array<Lattice, 3> lattice;
  /// nodes[0]*nodes[1]*nodes[2]*3 values; index ((k*n1 + j)*n0 + i)*3 + c, c = component 0..2.
  std::vector<double> correction_steps;
};

/// An AXIS1D table: correction of one axis as a function of its own position and direction.
struct AxisCorrections {
  uint8_t axis = 0;
  Lattice lattice;
  std::vector<double> forward_steps;  // nodes values, used when the axis last moved positive
  std::vector<double> reverse_steps;  // empty, or nodes values used when it last moved negative
  double backlash_steps = 0;          // added to the correction while moving negative
  uint32_t wrap_period_steps = 0;     // rotary wrap-around: 0 = none, else == (nodes-1)*spacing
};

/// The id the board reports in 0x2103 when no table is active; images carry ids from 1.
inline constexpr uint32_t kNoTableId = 0;

struct ImageRequest {
  uint32_t table_id = 1;      // 1..0xFFFFFFFF (kNoTableId is refused)
  std::vector<AxisDef> axes;  // 1..6
  std::optional<GridCorrections> grid;
  std::vector<AxisCorrections> axis_tables;
  table::ElementType element = table::ElementType::kInt16;
  /// Fraction bits for int16/int32 (0..8); nullopt = the largest that fits every value.
  std::optional<uint8_t> frac_bits;
  /// Free-form text for people (machine, date, source data); written as the INFO section.
  std::map<std::string, std::string> info;
  /// The thermal model, written as the THERMAL section (its axis_count = axes.size()).
  std::optional<thermal::ThermalModel> thermal;
};

/// Builds and validates an image (kInputInvalid naming the problem).
Expected<std::vector<uint8_t>> BuildImage(const ImageRequest& request);

/// Largest fraction bits (0..8) at which every value fits the element type; kInputInvalid when
/// even 0 does not fit or a value exceeds table::kMaxCorrectionSteps.
Expected<uint8_t> ChooseFracBits(const ImageRequest& request);

}  // namespace volcomp::image
