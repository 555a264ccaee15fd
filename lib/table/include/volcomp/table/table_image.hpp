// Parsing and validation of a table image into a read-only view (no copy, no heap).
//
// ParseImage() checks every field of the container and of each section (see table_format.hpp and
// docs/table-image-format.md) and returns a TableView whose pointers refer into the image bytes,
// so the image must outlive the view. Validation never reads outside [data, data + size), checks
// sizes without overflow, refuses NaN/Inf and out-of-range values, and reports the first problem
// as a distinct Error. It never writes anything. Cost: O(image size) (every element is checked);
// call it when an image is staged or activated, never on the control tick.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::table {

struct AxisInfo {
  char name = 0;
  AxisKind kind = AxisKind::kLinear;
  uint32_t resolution_e9 = 0;  // units per step x 1e9
};

/// One lattice dimension: node i sits at origin_steps + i * spacing_steps.
struct Dimension {
  uint32_t nodes = 0;
  int32_t origin_steps = 0;
  uint32_t spacing_steps = 0;
};

struct Grid3View {
  bool present = false;
  ElementType type = ElementType::kInt16;
  uint8_t frac_bits = 0;
  uint8_t axis[3] = {0, 1, 2};  // board axis of dimension d and of component d
  Dimension dim[3];
  const uint8_t* data = nullptr;  // nodes0*nodes1*nodes2*3 elements, x fastest, xyz interleaved
};

struct Axis1dView {
  uint8_t axis = 0;
  ElementType type = ElementType::kInt16;
  uint8_t frac_bits = 0;
  uint8_t flags = 0;
  Dimension dim;
  uint32_t period_steps = 0;         // wrap period, 0 = no wrap
  int32_t backlash_q8 = 0;           // added while the axis moves negative
  const uint8_t* forward = nullptr;  // dim.nodes elements
  const uint8_t* reverse = nullptr;  // dim.nodes elements, or null (use forward)
};

struct TableView {
  uint32_t image_size = 0;
  uint32_t crc32 = 0;  // the trailer value (CRC-32 of everything before it)
  uint32_t table_id = 0;
  uint8_t version_minor = 0;
  uint8_t axis_count = 0;
  AxisInfo axes[kMaxAxes];
  Grid3View grid;
  uint8_t axis1d_count = 0;
  Axis1dView axis1d[kMaxAxes];
  const char* info = nullptr;  // INFO text (not NUL-terminated), or null
  uint32_t info_size = 0;
  const uint8_t* thermal = nullptr;  // THERMAL body (validated), or null: ReadThermal()
};

/// Validates `size` bytes at `data` as one complete image (image_size must equal `size`).
/// `data` must be 4-byte aligned (kImageMisaligned otherwise).
Result<TableView> ParseImage(const uint8_t* data, size_t size);

/// Reads only the image_size field of a header (for storage that holds an image of unknown
/// length); kImageTooShort / kImageBadMagic / kImageTooLarge when it cannot be a valid header.
Result<uint32_t> PeekImageSize(const uint8_t* data, size_t available);

/// The thermal model of a THERMAL body ParseImage() has validated (TableView::thermal).
thermal::ThermalModel ReadThermal(const uint8_t* body);

/// Value of element `index` of an array of `type` with `frac_bits`, in steps (host-side helper
/// for tools and tests; the interpolators read elements directly).
double ElementSteps(const uint8_t* array, ElementType type, uint8_t frac_bits, uint32_t index);

}  // namespace volcomp::table
