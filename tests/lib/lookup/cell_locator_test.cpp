// Division-free lattice locations against exact integer arithmetic.
#include "volcomp/lookup/cell_locator.hpp"

#include <gtest/gtest.h>

#include <random>

namespace volcomp {
namespace {

// LatticeLocator against exact integer arithmetic: with u = clamp(pos) - origin and the exact cell
// coordinate E = u * 2^32 / spacing, the result X = cell * 2^32 + frac is E for u = 0 and otherwise
// strictly below E by less than 2 units (cell_locator.hpp); off the nodes the cell is exact.
void CheckLocate(const table::Dimension& dim, int32_t pos) {
  LatticeLocator loc;
  loc.Init(dim);
  const int64_t lo = dim.origin_steps;
  const int64_t hi = lo + int64_t{dim.nodes - 1} * dim.spacing_steps;
  const int64_t p = pos < lo ? lo : (pos > hi ? hi : pos);
  const uint64_t u = static_cast<uint64_t>(p - lo);
  const uint64_t q = (u << 32) / dim.spacing_steps, r = (u << 32) % dim.spacing_steps;
  const LatticeCell c = loc.Locate(pos);
  const uint64_t x = (uint64_t{c.cell} << 32) | c.frac_q32;
  ASSERT_LE(c.cell, dim.nodes - 2) << pos;
  if (u == 0) {
    ASSERT_EQ(x, 0u) << pos;
    return;
  }
  ASSERT_TRUE(x < q || (x == q && r != 0)) << "not below the exact value: pos " << pos;
  ASSERT_LE(q - x, 1u) << "pos " << pos << " spacing " << dim.spacing_steps;
  if (u % dim.spacing_steps != 0) {
    ASSERT_EQ(c.cell, u / dim.spacing_steps) << "pos " << pos << " spacing " << dim.spacing_steps;
  }
}

TEST(LatticeLocator, MatchesExactArithmetic) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 2000; ++i) {
    table::Dimension dim;
    dim.nodes = 2 + static_cast<uint32_t>(rng() % 40);
    const uint32_t max_spacing = 0x7FFFFFFFu / (dim.nodes - 1);
    dim.spacing_steps = 1 + static_cast<uint32_t>((rng() >> (rng() % 40)) % max_spacing);
    const int64_t extent = int64_t{dim.nodes - 1} * dim.spacing_steps;
    dim.origin_steps = static_cast<int32_t>(
        INT32_MIN +
        static_cast<int64_t>(rng() % static_cast<uint64_t>(int64_t{UINT32_MAX} - extent + 1)));
    const int32_t lo = dim.origin_steps;
    const int32_t hi = static_cast<int32_t>(lo + extent);
    const int32_t special[] = {lo, hi, INT32_MIN, INT32_MAX, lo + 1, hi - 1};
    for (int32_t p : special) CheckLocate(dim, p);
    for (uint32_t n = 0; n < dim.nodes; ++n) {
      const int64_t node = lo + int64_t{n} * dim.spacing_steps;
      for (int64_t d = -1; d <= 1; ++d) {
        const int64_t q = node + d;
        if (q >= INT32_MIN && q <= INT32_MAX) CheckLocate(dim, static_cast<int32_t>(q));
      }
    }
    for (int k = 0; k < 50; ++k) CheckLocate(dim, static_cast<int32_t>(rng()));
  }
}

TEST(LatticeLocator, NodesEndThePreviousCellAndTheEndsClamp) {
  LatticeLocator loc;
  loc.Init({5, -30, 7});
  EXPECT_EQ(loc.Locate(-30).cell, 0u);  // the first node: cell 0 at fraction 0
  EXPECT_EQ(loc.Locate(-30).frac_q32, 0u);
  EXPECT_EQ(loc.Locate(-1000).cell, 0u);  // below: held at the first node
  EXPECT_EQ(loc.Locate(-1000).frac_q32, 0u);
  EXPECT_EQ(loc.Locate(-23).cell, 0u);  // node 1: the end of cell 0
  EXPECT_GE(loc.Locate(-23).frac_q32, 0xFFFFFFFEu);
  EXPECT_EQ(loc.Locate(-22).cell, 1u);  // just past node 1
  EXPECT_EQ(loc.Locate(-2).cell, 3u);   // the last node: the end of the last cell
  EXPECT_GE(loc.Locate(-2).frac_q32, 0xFFFFFFFEu);
  EXPECT_EQ(loc.Locate(1000).cell, 3u);  // above: held at the last node
  EXPECT_EQ(loc.Locate(1000).frac_q32, loc.Locate(-2).frac_q32);
}

}  // namespace
}  // namespace volcomp
