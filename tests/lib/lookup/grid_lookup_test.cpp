// Trilinear lookup against an exact double-precision reference on random tables and points.
#include "volcomp/lookup/grid_lookup.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "test_tables.hpp"

namespace volcomp {
namespace {

using testing::GridCase;

constexpr double kLsb = 1.0 / 256.0;  // Q24.8 output LSB, in steps

struct ErrorStats {
  double max_abs_lsb = 0;
  uint64_t points = 0;
};

// Random positions: nodes, cell faces/edges (some coordinates on nodes), interior, outside.
int32_t RandomCoordinate(std::mt19937_64& rng, const table::Dimension& d) {
  const int64_t lo = d.origin_steps, span = int64_t{d.nodes - 1} * d.spacing_steps;
  const int64_t node = lo + int64_t(rng() % d.nodes) * d.spacing_steps;
  switch (rng() % 6) {
    case 0:
      return static_cast<int32_t>(node);
    case 1:
      return static_cast<int32_t>(std::max<int64_t>(lo - 1 - int64_t(rng() % 100000), INT32_MIN));
    case 2:
      return static_cast<int32_t>(
          std::min<int64_t>(lo + span + 1 + int64_t(rng() % 100000), INT32_MAX));
    case 3:
      return static_cast<int32_t>(std::min(node + 1, lo + span));
    default:
      return static_cast<int32_t>(lo + int64_t(rng() % uint64_t(span + 1)));
  }
}

ErrorStats RunRandom(table::ElementType type,
                     uint64_t seed,
                     int tables,
                     int points_per_table,
                     uint32_t max_spacing,
                     double amplitude_steps) {
  std::mt19937_64 rng(seed);
  ErrorStats stats;
  for (int t = 0; t < tables; ++t) {
    const GridCase g = testing::RandomGrid(rng, type, 9, max_spacing, amplitude_steps);
    const testing::AlignedBytes img = testing::WriteGridImage(g);
    EXPECT_GT(img.size(), 0u);
    if (img.size() == 0) return stats;
    const auto view = table::ParseImage(img.data(), img.size());
    EXPECT_TRUE(view.ok()) << view.status().name();
    GridLookup lookup;
    EXPECT_TRUE(lookup.Init(view->grid).ok());
    for (int i = 0; i < points_per_table; ++i) {
      int32_t pos[3];
      for (int d = 0; d < 3; ++d) pos[d] = RandomCoordinate(rng, g.dim[d]);
      int32_t out[3];
      lookup.Lookup(pos, out);
      for (int c = 0; c < 3; ++c) {
        const double exact = testing::ExactTrilinear(g, pos, c);
        const double err = std::fabs(out[c] * kLsb - exact) / kLsb;
        stats.max_abs_lsb = std::max(stats.max_abs_lsb, err);
      }
      ++stats.points;
    }
  }
  return stats;
}

TEST(GridLookup, Int16WithinOneLsbOfExact) {
  const ErrorStats s = RunRandom(table::ElementType::kInt16, 11, 100, 1000, 100000, 1e6);
  EXPECT_GE(s.points, 100000u);
  EXPECT_LE(s.max_abs_lsb, 1.0);
  std::printf("[ metric ] int16 grid: %llu points, max |error| = %.4f LSB (Q8)\n",
              static_cast<unsigned long long>(s.points), s.max_abs_lsb);
}

TEST(GridLookup, Int32WithinOneLsbOfExactAcrossFullRange) {
  // Values up to the format limit (65536 steps) and spacings up to ~2^31 / nodes.
  const ErrorStats s = RunRandom(table::ElementType::kInt32, 12, 100, 1000, 200000000, 65536);
  EXPECT_GE(s.points, 100000u);
  EXPECT_LE(s.max_abs_lsb, 1.0);
  std::printf("[ metric ] int32 grid: %llu points, max |error| = %.4f LSB (Q8)\n",
              static_cast<unsigned long long>(s.points), s.max_abs_lsb);
}

TEST(GridLookup, Float32WithinDocumentedTolerance) {
  // Documented: |error| <= 1 LSB + 2^-20 * max|value| (float32 carries 24 bits).
  const double amplitude = 1000;
  const ErrorStats s = RunRandom(table::ElementType::kFloat32, 13, 100, 1000, 100000, amplitude);
  EXPECT_GE(s.points, 100000u);
  EXPECT_LE(s.max_abs_lsb, 1.0 + std::ldexp(amplitude, -20) / kLsb);
  std::printf("[ metric ] float32 grid (|v| <= %g steps): %llu points, max |error| = %.4f LSB\n",
              amplitude, static_cast<unsigned long long>(s.points), s.max_abs_lsb);
}

TEST(GridLookup, NodesAreExactAndOutsideHoldsBoundary) {
  std::mt19937_64 rng(5);
  GridCase g = testing::RandomGrid(rng, table::ElementType::kInt32, 4, 1000, 100);
  const testing::AlignedBytes img = testing::WriteGridImage(g);
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  GridLookup lookup;
  ASSERT_TRUE(lookup.Init(view->grid).ok());
  for (uint32_t k = 0; k < g.dim[2].nodes; ++k) {
    for (uint32_t j = 0; j < g.dim[1].nodes; ++j) {
      for (uint32_t i = 0; i < g.dim[0].nodes; ++i) {
        const int32_t pos[3] = {
            static_cast<int32_t>(g.dim[0].origin_steps + int64_t{i} * g.dim[0].spacing_steps),
            static_cast<int32_t>(g.dim[1].origin_steps + int64_t{j} * g.dim[1].spacing_steps),
            static_cast<int32_t>(g.dim[2].origin_steps + int64_t{k} * g.dim[2].spacing_steps)};
        int32_t out[3];
        lookup.Lookup(pos, out);
        for (int c = 0; c < 3; ++c) {
          const size_t idx = ((size_t{k} * g.dim[1].nodes + j) * g.dim[0].nodes + i) * 3 + c;
          EXPECT_NEAR(out[c] * kLsb, g.steps[idx], kLsb / 2) << i << j << k << c;
        }
      }
    }
  }
  // Far outside equals the clamped corner.
  int32_t far[3] = {INT32_MIN, INT32_MAX, INT32_MIN}, corner[3];
  for (int d = 0; d < 3; ++d) {
    corner[d] = d == 1 ? static_cast<int32_t>(g.dim[1].origin_steps +
                                              int64_t{g.dim[1].nodes - 1} * g.dim[1].spacing_steps)
                       : g.dim[d].origin_steps;
  }
  int32_t a[3], b[3];
  lookup.Lookup(far, a);
  lookup.Lookup(corner, b);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]);
}

TEST(GridLookup, AxisMappingSelectsPositionsAndComponents) {
  // Grid over board axes (Z, X, Y): dimension d reads axis map[d]; component d corrects it.
  std::vector<int16_t> v(2 * 2 * 2 * 3, 0);
  // Only the node at dim-0 index 1 (board axis 2 = Z high) has component 0 = 256 (1 step).
  for (int node = 0; node < 8; ++node) {
    if (node & 1) v[node * 3 + 0] = 256;
  }
  table::GridSpec g;
  g.frac_bits = 8;
  g.axis[0] = 2;
  g.axis[1] = 0;
  g.axis[2] = 1;
  for (auto& d : g.dim) d = {2, 0, 100};
  g.values.i16 = v.data();
  const testing::AlignedBytes img = testing::WriteImageBytes(testing::XyzImageSpec(g));
  ASSERT_NE(img.size(), 0u);
  const auto view = table::ParseImage(img.data(), img.size());
  GridLookup lookup;
  ASSERT_TRUE(lookup.Init(view->grid).ok());
  int32_t out[3];
  const int32_t z_mid[3] = {0, 0, 50};  // X=0, Y=0, Z=50
  lookup.Lookup(z_mid, out);
  EXPECT_EQ(out[0], 128);  // half a step on component 0, which corrects axis 2 (Z)
  EXPECT_EQ(lookup.axis(0), 2);
  const int32_t x_mid[3] = {50, 0, 0};
  lookup.Lookup(x_mid, out);
  EXPECT_EQ(out[0], 0);
}

}  // namespace
}  // namespace volcomp
