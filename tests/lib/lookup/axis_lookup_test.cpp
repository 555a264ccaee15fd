// AXIS1D lookup: interpolation, direction tables, backlash, wrap-around.
#include "volcomp/lookup/axis_lookup.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "test_tables.hpp"

namespace volcomp {
namespace {

struct OneAxis {
  testing::AlignedBytes img;
  table::TableView view;
};

OneAxis Build(const table::Axis1dSpec& a, table::AxisKind kind = table::AxisKind::kLinear) {
  table::ImageSpec s;
  s.axis_count = 1;
  s.axes[0] = {kind == table::AxisKind::kRotary ? 'A' : 'X', kind, 1000000};
  s.axis1d_count = 1;
  s.axis1d[0] = a;
  OneAxis o;
  o.img = testing::AlignedBytes(*table::ImageSize(s));
  EXPECT_TRUE(table::WriteImage(s, o.img.data(), o.img.size()).ok());
  o.view = *table::ParseImage(o.img.data(), o.img.size());
  return o;
}

TEST(AxisLookup, LinearInterpolationAgainstExact) {
  std::mt19937_64 rng(3);
  for (int t = 0; t < 200; ++t) {
    const uint32_t n = 2 + static_cast<uint32_t>(rng() % 50);
    table::Axis1dSpec a;
    a.frac_bits = static_cast<uint8_t>(rng() % 9);
    const int64_t max_lsb = int64_t{table::kMaxCorrectionSteps} << a.frac_bits;
    std::vector<int32_t> fwd(n);
    for (auto& v : fwd)
      v = static_cast<int32_t>(int64_t(rng() % uint64_t(2 * max_lsb + 1)) - max_lsb);
    a.dim = {n, static_cast<int32_t>(rng() % 100000) - 50000,
             1 + static_cast<uint32_t>(rng() % 100000)};
    a.forward.type = table::ElementType::kInt32;
    a.forward.i32 = fwd.data();
    const OneAxis o = Build(a);
    AxisLookup lookup;
    ASSERT_TRUE(lookup.Init(o.view.axis1d[0]).ok());
    for (int i = 0; i < 500; ++i) {
      const int64_t span = int64_t{n - 1} * a.dim.spacing_steps;
      const int32_t pos =
          static_cast<int32_t>(a.dim.origin_steps - 1000 + int64_t(rng() % uint64_t(span + 2000)));
      const double u = std::min(std::max(double(pos - a.dim.origin_steps), 0.0), double(span)) /
                       a.dim.spacing_steps;
      const uint32_t c = std::min<uint32_t>(static_cast<uint32_t>(u), n - 2);
      const double exact =
          (fwd[c] + (fwd[c + 1] - fwd[c]) * (u - c)) / std::ldexp(1.0, a.frac_bits);
      EXPECT_NEAR(lookup.Lookup(pos, false) / 256.0, exact, 1.0 / 256.0) << pos;
    }
  }
}

TEST(AxisLookup, ReverseTableAndBacklash) {
  std::vector<int16_t> fwd = {0, 256, 512}, rev = {100, 100, 100};
  table::Axis1dSpec a;
  a.frac_bits = 8;
  a.dim = {3, 0, 1000};
  a.forward.i16 = fwd.data();
  a.has_reverse = true;
  a.reverse.i16 = rev.data();
  a.backlash_q8 = -50;
  OneAxis o = Build(a);
  AxisLookup lookup;
  ASSERT_TRUE(lookup.Init(o.view.axis1d[0]).ok());
  EXPECT_EQ(lookup.Lookup(500, false), 128);      // half-way 0 -> 1 step, Q8
  EXPECT_EQ(lookup.Lookup(500, true), 100 - 50);  // reverse table plus backlash
  // Without a reverse table, the reverse direction is forward + backlash.
  a.has_reverse = false;
  o = Build(a);
  ASSERT_TRUE(lookup.Init(o.view.axis1d[0]).ok());
  EXPECT_EQ(lookup.Lookup(1500, true), 384 - 50);
}

TEST(WrapTracker, FollowsDeltasModuloThePeriod) {
  std::mt19937_64 rng(4);
  WrapTracker w;
  const uint32_t period = 36000;
  int64_t abs_pos = -123456;
  w.Init(static_cast<int32_t>(abs_pos), 100, period);
  for (int i = 0; i < 100000; ++i) {
    const int32_t d = static_cast<int32_t>(rng() % 2001) - 1000;
    abs_pos += d;
    const int32_t got = w.Update(d);
    int64_t expect = (abs_pos - 100) % period;
    if (expect < 0) expect += period;
    ASSERT_EQ(got, expect + 100) << i;
  }
}

TEST(AxisLookup, RotaryWrapTableIsContinuousAcrossTheSeam) {
  std::vector<int32_t> v = {0, 1000, -500, 0};  // period 3000 steps, equal ends
  table::Axis1dSpec a;
  a.dim = {4, 0, 1000};
  a.period_steps = 3000;
  a.forward.type = table::ElementType::kInt32;
  a.forward.i32 = v.data();
  const OneAxis o = Build(a, table::AxisKind::kRotary);
  AxisLookup lookup;
  ASSERT_TRUE(lookup.Init(o.view.axis1d[0]).ok());
  EXPECT_TRUE(lookup.wraps());
  WrapTracker w;
  w.Init(2990, 0, 3000);
  const int32_t before = lookup.Lookup(w.position(), false);
  const int32_t after = lookup.Lookup(w.Update(20), false);  // crosses 3000 -> 10
  EXPECT_EQ(w.position(), 10);
  EXPECT_NEAR(before, -5 * 256, 256);
  EXPECT_NEAR(after, 10 * 256, 256);
  EXPECT_EQ(lookup.Lookup(0, false), lookup.Lookup(3000, false));
}

TEST(WrapTracker, InitWithAPreparedDivisorIsTheModuloOfTheDifference) {
  // Oracle: 64-bit remainder, made non-negative.
  const auto expected = [](int32_t pos, int32_t origin, uint32_t period) {
    int64_t o = (int64_t{pos} - origin) % int64_t{period};
    if (o < 0) o += period;
    return static_cast<int32_t>(static_cast<uint32_t>(origin) + static_cast<uint32_t>(o));
  };
  const int32_t edges[] = {INT32_MIN, INT32_MIN + 1, -3000, -2999,         -1,       0,
                           1,         2999,          3000,  INT32_MAX - 1, INT32_MAX};
  const uint32_t periods[] = {1, 2, 3, 3000, 65537, 0x7FFFFFFFu};
  std::mt19937 rng(5);
  for (const uint32_t period : periods) {
    InvariantDivider d;
    d.Init(period);
    for (const int32_t pos : edges) {
      for (const int32_t origin : edges) {
        WrapTracker w;
        w.Init(pos, origin, d);
        ASSERT_EQ(w.position(), expected(pos, origin, period))
            << pos << " " << origin << " " << period;
      }
    }
    for (int i = 0; i < 2000; ++i) {
      const auto pos = static_cast<int32_t>(rng()), origin = static_cast<int32_t>(rng());
      WrapTracker w;
      w.Init(pos, origin, d);
      ASSERT_EQ(w.position(), expected(pos, origin, period));
    }
  }
}

}  // namespace
}  // namespace volcomp
