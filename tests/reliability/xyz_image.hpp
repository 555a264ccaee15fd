// Test helper: an XYZ GRID3 image (int16, 4 fraction bits, 1 um/step axes) with given node values.
#pragma once

#include <cstdint>
#include <vector>

#include "volcomp/table/table_writer.hpp"

namespace volcomp::testing {

/// `values`: nodes^3 * 3 int16 elements (x fastest, components interleaved); nodes along each
/// axis from `origin_steps` every `spacing_steps`.
inline std::vector<uint8_t> XyzImage(uint32_t id,
                                     uint32_t nodes,
                                     int32_t origin_steps,
                                     uint32_t spacing_steps,
                                     const std::vector<int16_t>& values) {
  table::GridSpec g;
  g.frac_bits = 4;
  for (auto& d : g.dim) d = {nodes, origin_steps, spacing_steps};
  g.values.i16 = values.data();
  table::ImageSpec s;
  s.table_id = id;
  s.axis_count = 3;
  for (int a = 0; a < 3; ++a) s.axes[a] = {"XYZ"[a], table::AxisKind::kLinear, 1000000};
  s.grid = &g;
  std::vector<uint32_t> w((*table::ImageSize(s) + 3) / 4);
  const uint32_t n = *table::WriteImage(s, reinterpret_cast<uint8_t*>(w.data()), w.size() * 4);
  const uint8_t* p = reinterpret_cast<const uint8_t*>(w.data());
  return std::vector<uint8_t>(p, p + n);
}

}  // namespace volcomp::testing
