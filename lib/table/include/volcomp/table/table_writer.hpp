// Writing a table image into a caller-provided buffer (freestanding: used by the PC tool, the
// simulator and tests; the firmware only reads images).
//
// The caller describes the content with already-encoded element arrays (the raw little-endian
// element bytes are produced from the typed arrays here). WriteImage() lays out header, sections,
// padding and CRC exactly as ParseImage() expects, then runs ParseImage() on the result, so a
// successful write is always a valid image.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::table {

/// A typed element array: exactly one of the pointers is used, chosen by `type`.
struct ElementArray {
  ElementType type = ElementType::kInt16;
  const int16_t* i16 = nullptr;
  const int32_t* i32 = nullptr;
  const float* f32 = nullptr;
};

struct GridSpec {
  uint8_t frac_bits = 0;
  uint8_t axis[3] = {0, 1, 2};
  Dimension dim[3];
  ElementArray values;  // dim[0].nodes*dim[1].nodes*dim[2].nodes*3 elements
};

struct Axis1dSpec {
  uint8_t axis = 0;
  uint8_t frac_bits = 0;
  Dimension dim;
  uint32_t period_steps = 0;  // nonzero = wrap (sets kFlagWrap)
  int32_t backlash_q8 = 0;
  ElementArray forward;
  bool has_reverse = false;
  ElementArray reverse;  // same type as forward
};

struct ImageSpec {
  uint32_t table_id = 0;
  uint8_t axis_count = 0;
  AxisInfo axes[kMaxAxes];
  const GridSpec* grid = nullptr;  // optional
  uint8_t axis1d_count = 0;
  Axis1dSpec axis1d[kMaxAxes];
  const char* info = nullptr;  // optional INFO text
  uint32_t info_size = 0;
  const thermal::ThermalModel* thermal = nullptr;  // optional THERMAL (axis_count = axis_count)
};

/// Bytes the image for `spec` needs; kWriterBadArgument for inconsistent sizes.
Result<uint32_t> ImageSize(const ImageSpec& spec);

/// Writes the image into out[0, capacity) and validates it; returns its size. `out` must be
/// 4-byte aligned. On error the buffer content is unspecified.
Result<uint32_t> WriteImage(const ImageSpec& spec, uint8_t* out, size_t capacity);

}  // namespace volcomp::table
