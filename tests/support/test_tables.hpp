// Test helpers: random table images built with the real writer, byte patching with CRC fix-up,
// and an exact double-precision trilinear reference written independently of lib/.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "volcomp/base/byte_order.hpp"
#include "volcomp/base/crc32.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_image.hpp"
#include "volcomp/table/table_writer.hpp"

namespace volcomp::testing {

/// 4-byte aligned byte buffer.
class AlignedBytes {
 public:
  AlignedBytes() = default;
  explicit AlignedBytes(size_t n) : words_((n + 3) / 4 + 1), size_(n) {}
  AlignedBytes(const uint8_t* p, size_t n) : AlignedBytes(n) { std::memcpy(data(), p, n); }
  uint8_t* data() { return reinterpret_cast<uint8_t*>(words_.data()); }
  const uint8_t* data() const { return reinterpret_cast<const uint8_t*>(words_.data()); }
  size_t size() const { return size_; }
  void resize(size_t n) {
    words_.resize((n + 3) / 4 + 1);
    size_ = n;
  }
  uint8_t& operator[](size_t i) { return data()[i]; }

 private:
  std::vector<uint32_t> words_;
  size_t size_ = 0;
};

/// Recomputes the CRC trailer after a deliberate edit.
inline void FixCrc(AlignedBytes& img) {
  const size_t body = img.size() - table::kTrailerSize;
  StoreLe32(img.data() + body, ComputeCrc32(img.data(), body));
}

/// A grid table description with its values in steps (what the exact reference uses).
struct GridCase {
  table::ElementType type = table::ElementType::kInt16;
  uint8_t frac_bits = 0;
  table::Dimension dim[3];
  std::vector<int16_t> i16;
  std::vector<int32_t> i32;
  std::vector<float> f32;
  std::vector<double> steps;  // exact value of every element, in steps

  size_t count() const { return size_t{dim[0].nodes} * dim[1].nodes * dim[2].nodes * 3; }
};

/// Random grid: dims 2..max_nodes, spacing 1..max_spacing, values spanning `amplitude_steps`.
inline GridCase RandomGrid(std::mt19937_64& rng,
                           table::ElementType type,
                           uint32_t max_nodes,
                           uint32_t max_spacing,
                           double amplitude_steps) {
  GridCase g;
  g.type = type;
  std::uniform_int_distribution<uint32_t> nodes(2, max_nodes), spacing(1, max_spacing);
  std::uniform_int_distribution<int32_t> origin(-1000000, 1000000);
  for (auto& d : g.dim) d = {nodes(rng), origin(rng), spacing(rng)};
  if (type != table::ElementType::kFloat32) {
    g.frac_bits = static_cast<uint8_t>(std::uniform_int_distribution<int>(0, 8)(rng));
  }
  const double scale = std::ldexp(1.0, g.frac_bits);
  const double lim = type == table::ElementType::kInt16 ? 32767.0 : std::ldexp(1.0, 24);
  const double amp_lsb = std::min(amplitude_steps * scale, lim);
  std::uniform_real_distribution<double> value(-amp_lsb, amp_lsb);
  for (size_t i = 0; i < g.count(); ++i) {
    const double v = std::round(value(rng));
    switch (type) {
      case table::ElementType::kInt16:
        g.i16.push_back(static_cast<int16_t>(v));
        g.steps.push_back(v / scale);
        break;
      case table::ElementType::kInt32:
        g.i32.push_back(static_cast<int32_t>(v));
        g.steps.push_back(v / scale);
        break;
      case table::ElementType::kFloat32: {
        const float f = static_cast<float>(value(rng) / scale);
        g.f32.push_back(f);
        g.steps.push_back(f);
        break;
      }
    }
  }
  return g;
}

inline table::AxisInfo LinearAxis(char name, uint32_t resolution_e9 = 1000000) {
  return {name, table::AxisKind::kLinear, resolution_e9};
}

/// An image of linear axes X, Y, Z (1 µm per step) holding `grid` (which must outlive it).
inline table::ImageSpec XyzImageSpec(const table::GridSpec& grid, uint32_t table_id = 0) {
  table::ImageSpec img;
  img.table_id = table_id;
  img.axis_count = 3;
  img.axes[0] = LinearAxis('X');
  img.axes[1] = LinearAxis('Y');
  img.axes[2] = LinearAxis('Z');
  img.grid = &grid;
  return img;
}

/// The image of `spec` as the real writer writes it; empty when the writer refuses it.
inline AlignedBytes WriteImageBytes(const table::ImageSpec& spec) {
  const Result<uint32_t> size = table::ImageSize(spec);
  AlignedBytes out(size.ok() ? *size : 0);
  const Result<uint32_t> w = table::WriteImage(spec, out.data(), out.size());
  if (!w.ok()) out.resize(0);
  return out;
}

/// Writes an XYZ image holding `g` (and optional extra AXIS1D specs); empty on failure.
inline AlignedBytes WriteGridImage(const GridCase& g,
                                   uint32_t table_id = 7,
                                   const table::Axis1dSpec* axis1d = nullptr,
                                   uint8_t axis1d_count = 0) {
  table::GridSpec spec;
  spec.frac_bits = g.frac_bits;
  for (int d = 0; d < 3; ++d) spec.dim[d] = g.dim[d];
  spec.values.type = g.type;
  spec.values.i16 = g.i16.data();
  spec.values.i32 = g.i32.data();
  spec.values.f32 = g.f32.data();
  table::ImageSpec img = XyzImageSpec(spec, table_id);
  for (uint8_t i = 0; i < axis1d_count; ++i) img.axis1d[i] = axis1d[i];
  img.axis1d_count = axis1d_count;
  return WriteImageBytes(img);
}

/// Exact trilinear interpolation in double (clamped), independent of lib/: value of component c.
inline double ExactTrilinear(const GridCase& g, const int32_t pos[3], int c) {
  double t[3];
  uint32_t i0[3];
  for (int d = 0; d < 3; ++d) {
    const double lo = g.dim[d].origin_steps;
    const double hi = lo + double(g.dim[d].nodes - 1) * g.dim[d].spacing_steps;
    const double p = std::min(std::max(double(pos[d]), lo), hi);
    const double u = (p - lo) / g.dim[d].spacing_steps;
    double cell = std::floor(u);
    if (cell > g.dim[d].nodes - 2) cell = g.dim[d].nodes - 2;
    i0[d] = static_cast<uint32_t>(cell);
    t[d] = u - cell;
  }
  auto at = [&](uint32_t i, uint32_t j, uint32_t k) {
    return g.steps[((size_t{k} * g.dim[1].nodes + j) * g.dim[0].nodes + i) * 3 + c];
  };
  double r = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const int bx = corner & 1, by = (corner >> 1) & 1, bz = (corner >> 2) & 1;
    const double w = (bx ? t[0] : 1 - t[0]) * (by ? t[1] : 1 - t[1]) * (bz ? t[2] : 1 - t[2]);
    r += w * at(i0[0] + bx, i0[1] + by, i0[2] + bz);
  }
  return r;
}

}  // namespace volcomp::testing
