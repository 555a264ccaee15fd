// Host side of the bit-identity check: the host computes the golden stream and it must equal the
// checked-in golden_vectors.inc, which the QEMU image compares with the Cortex-M4F results; and
// the hot-path lookup must equal the clear reference bit for bit on random tables too.
#include <gtest/gtest.h>

#include <random>

#include "golden_stream.hpp"
#include "test_tables.hpp"
#include "volcomp/lookup/grid_lookup.hpp"

namespace volcomp::target {
namespace {

class GoldenTest : public ::testing::TestWithParam<int> {};

TEST_P(GoldenTest, HostMatchesCheckedInVectors) {
  const auto s = static_cast<GoldenSection>(GetParam());
  CompareSink sink;
  uint32_t mismatches = 0;
  ComputeGolden(s, sink, &mismatches);
  EXPECT_EQ(mismatches, 0u) << "hot path differs from the reference";
  EXPECT_TRUE(sink.ok()) << GoldenSectionName(s) << ": " << sink.computed() << " words computed, "
                         << sink.expected() << " checked in; first difference at word "
                         << sink.first_diff() << " (got 0x" << std::hex << sink.got() << ", file 0x"
                         << sink.want() << std::dec
                         << "). If the change is intended, regenerate with golden_gen "
                            "(tests/target/golden_gen.cpp).";
}

INSTANTIATE_TEST_SUITE_P(Sections,
                         GoldenTest,
                         ::testing::Range(1, static_cast<int>(GoldenSection::kCount)),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return std::string(
                               GoldenSectionName(static_cast<GoldenSection>(i.param)));
                         });

// The optimised kernels against the clear template on the random tables of the accuracy tests.
TEST(HotPathLookup, BitIdenticalToReferenceOnRandomTables) {
  std::mt19937_64 rng(21);
  const table::ElementType types[] = {table::ElementType::kInt16, table::ElementType::kInt32,
                                      table::ElementType::kFloat32};
  uint64_t points = 0;
  for (table::ElementType type : types) {
    for (int t = 0; t < 60; ++t) {
      const testing::GridCase g = testing::RandomGrid(rng, type, 9, 200000, 65536);
      const testing::AlignedBytes img = testing::WriteGridImage(g);
      ASSERT_GT(img.size(), 0u);
      const auto view = table::ParseImage(img.data(), img.size());
      ASSERT_TRUE(view.ok());
      GridLookup lookup;
      ASSERT_TRUE(lookup.Init(view->grid).ok());
      for (int i = 0; i < 2000; ++i) {
        int32_t pos[3];
        for (int d = 0; d < 3; ++d) {
          const int64_t lo = g.dim[d].origin_steps;
          const int64_t span = int64_t{g.dim[d].nodes - 1} * g.dim[d].spacing_steps;
          pos[d] = static_cast<int32_t>(lo - 1000 + int64_t(rng() % uint64_t(span + 2001)));
        }
        int32_t fast[3], ref[3];
        lookup.Lookup(pos, fast);
        if (type == table::ElementType::kInt16) lookup.Interpolate<LoadInt16>(pos, ref);
        if (type == table::ElementType::kInt32) lookup.Interpolate<LoadInt32>(pos, ref);
        if (type == table::ElementType::kFloat32) lookup.Interpolate<LoadFloat32>(pos, ref);
        for (int c = 0; c < 3; ++c) ASSERT_EQ(fast[c], ref[c]) << "type " << int(type);
        ++points;
      }
    }
  }
  std::printf("[ metric ] hot path == reference on %llu random points\n",
              static_cast<unsigned long long>(points));
}

}  // namespace
}  // namespace volcomp::target
