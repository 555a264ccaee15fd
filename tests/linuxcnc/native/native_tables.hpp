// Tables for the native component's tests, written by the real image writer: a random XYZ grid
// (1 um steps, origin 0) and the same grid with a rotary A axis whose AXIS1D table wraps.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "native/native_table.hpp"
#include "test_tables.hpp"

namespace volcomp::linuxcnc::testing {

using volcomp::testing::GridCase;

/// 1 um per step; positions in mm.
inline constexpr double kMmPerStep = 0.001;
/// The A axis: 0.001 degree per step, a 360-degree wrap table with a node every degree.
inline constexpr double kDegPerStep = 0.001;
inline constexpr uint32_t kANodes = 361;

inline GridCase Grid(uint64_t seed, double amplitude_steps) {
  std::mt19937_64 rng(seed);
  GridCase g =
      volcomp::testing::RandomGrid(rng, table::ElementType::kInt16, 5, 1000, amplitude_steps);
  for (auto& d : g.dim) d.origin_steps = 0;
  return g;
}

inline std::vector<uint8_t> Bytes(const volcomp::testing::AlignedBytes& a) {
  return std::vector<uint8_t>(a.data(), a.data() + a.size());
}

inline std::unique_ptr<NativeTable> Load(const volcomp::testing::AlignedBytes& image,
                                         const std::string& source = "test.vct") {
  Expected<std::unique_ptr<NativeTable>> t = NativeTable::FromBytes(Bytes(image), source);
  return t.ok() ? std::move(*t) : nullptr;
}

/// The A table's value at node i, in steps (a whole period of a sine: first = last node).
inline int16_t AValue(uint32_t i) {
  return static_cast<int16_t>(std::lround(40.0 * std::sin(2 * M_PI * i / (kANodes - 1))));
}

/// Grid `g` on X Y Z plus a rotary A with a wrapping AXIS1D table (values AValue, no reverse).
inline volcomp::testing::AlignedBytes XyzaImage(const GridCase& g) {
  static std::vector<int16_t> a_values;
  a_values.clear();
  for (uint32_t i = 0; i < kANodes; ++i) a_values.push_back(AValue(i));
  table::GridSpec grid;
  grid.frac_bits = g.frac_bits;
  for (int d = 0; d < 3; ++d) grid.dim[d] = g.dim[d];
  grid.values.type = g.type;
  grid.values.i16 = g.i16.data();
  table::ImageSpec img;
  img.table_id = 9;
  img.axis_count = 4;
  img.axes[0] = volcomp::testing::LinearAxis('X');
  img.axes[1] = volcomp::testing::LinearAxis('Y');
  img.axes[2] = volcomp::testing::LinearAxis('Z');
  img.axes[3] = {'A', table::AxisKind::kRotary, 1000000};  // 0.001 deg per step
  img.grid = &grid;
  img.axis1d_count = 1;
  table::Axis1dSpec& a = img.axis1d[0];
  a.axis = 3;
  a.dim = {kANodes, 0, 1000};
  a.period_steps = (kANodes - 1) * 1000;
  a.forward.type = table::ElementType::kInt16;
  a.forward.i16 = a_values.data();
  volcomp::testing::AlignedBytes out(*table::ImageSize(img));
  if (!table::WriteImage(img, out.data(), out.size()).ok()) out.resize(0);
  return out;
}

}  // namespace volcomp::linuxcnc::testing
