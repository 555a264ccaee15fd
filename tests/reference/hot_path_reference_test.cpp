// The optimised tick routines against their clear reference versions, bit for bit, on random and
// adversarial inputs (docs/mcu-target.md, "Changes made in lib/ for speed"):
//   LocateFast()                 vs LatticeLocator::Locate()
//   GridLookup::Lookup() and its three-part form (Begin/AccumulateZ0/FinishZ1)
//                                vs GridLookup::Interpolate<Loader>()
//   AxisLookup::Lookup()         vs AxisLookup::LookupReference()
//   StepGenerator::Plan()        vs StepGeneratorReference::Plan() (int64 times)
//   CorrectionLimiter::Step()    vs LimiterStepReference()
//   WrapTracker::Update()        vs exact modular arithmetic
#include "volcomp/reference/hot_path_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "test_tables.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/lookup/axis_lookup.hpp"
#include "volcomp/lookup/cell_locator.hpp"
#include "volcomp/lookup/grid_lookup.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp {
namespace {

// Positions that stress a dimension: the limits, their neighbours, every node +/- 1, far
// outside, the int32 extremes, and random points inside and around.
std::vector<int32_t> AdversarialPositions(const table::Dimension& d, std::mt19937_64& rng) {
  const int64_t lo = d.origin_steps, hi = lo + int64_t{d.nodes - 1} * d.spacing_steps;
  std::vector<int64_t> p = {INT32_MIN, INT32_MAX, INT32_MIN + 1, INT32_MAX - 1, lo, hi,
                            lo - 1,    hi + 1,    lo + 1,        hi - 1,        0,  -1};
  for (uint32_t n = 0; n < d.nodes; ++n) {
    const int64_t node = lo + int64_t{n} * d.spacing_steps;
    for (int64_t k = -1; k <= 1; ++k) p.push_back(node + k);
  }
  for (int i = 0; i < 32; ++i) {
    p.push_back(
        lo - 2 * d.spacing_steps +
        static_cast<int64_t>(rng() % (static_cast<uint64_t>(hi - lo) + 4u * d.spacing_steps + 1)));
  }
  std::vector<int32_t> out;
  for (int64_t v : p) {
    if (v >= INT32_MIN && v <= INT32_MAX) out.push_back(static_cast<int32_t>(v));
  }
  return out;
}

table::Dimension RandomDimension(std::mt19937_64& rng, uint32_t max_nodes) {
  table::Dimension d;
  d.nodes = 2 + static_cast<uint32_t>(rng() % (max_nodes - 1));
  const uint32_t max_spacing = table::kMaxExtentSteps / (d.nodes - 1);
  // Spacings across all magnitudes: 1 .. the extent limit.
  d.spacing_steps = 1 + static_cast<uint32_t>((rng() >> (rng() % 63)) % max_spacing);
  const int64_t extent = int64_t{d.nodes - 1} * d.spacing_steps;
  d.origin_steps = static_cast<int32_t>(
      INT32_MIN + static_cast<int64_t>(rng() % (uint64_t{UINT32_MAX} - extent + 1)));
  return d;
}

TEST(HotPathReference, LocateFastEqualsLocate) {
  std::mt19937_64 rng(101);
  uint64_t n = 0;
  for (int t = 0; t < 3000; ++t) {
    table::Dimension d = RandomDimension(rng, 1024);
    if (t == 0) d = {2, INT32_MIN, table::kMaxExtentSteps};  // the largest extent
    if (t == 1) d = {1024, 0, 1};                            // the smallest spacing
    LatticeLocator loc;
    loc.Init(d);
    for (int32_t p : AdversarialPositions(d, rng)) {
      const LatticeCell a = loc.Locate(p), b = LocateFast(p, loc.dim());
      ASSERT_EQ(a.cell, b.cell) << p;
      ASSERT_EQ(a.frac_q32, b.frac_q32) << p;
      ++n;
    }
  }
  std::printf("[ metric ] LocateFast == Locate on %llu positions\n",
              static_cast<unsigned long long>(n));
}

// A grid whose values sit at the format limits (every corner difference as large as possible).
testing::GridCase ExtremeGrid(std::mt19937_64& rng, table::ElementType type) {
  testing::GridCase g = testing::RandomGrid(rng, type, 7, 50000, 65536);
  const double scale = std::ldexp(1.0, g.frac_bits);
  for (size_t i = 0; i < g.count(); ++i) {
    const bool high = (rng() & 1) != 0;
    switch (type) {
      case table::ElementType::kInt16:
        g.i16[i] = high ? 32767 : -32767;
        g.steps[i] = g.i16[i] / scale;
        break;
      case table::ElementType::kInt32:
        g.i32[i] = (high ? 1 : -1) * (table::kMaxCorrectionSteps << g.frac_bits);
        g.steps[i] = g.i32[i] / scale;
        break;
      case table::ElementType::kFloat32:
        g.f32[i] = high ? 65536.0f : -65535.99609375f;
        g.steps[i] = g.f32[i];
        break;
    }
  }
  return g;
}

template <class Loader>
void CheckGrid(const testing::GridCase& g, std::mt19937_64& rng, uint64_t* points) {
  const testing::AlignedBytes img = testing::WriteGridImage(g);
  ASSERT_GT(img.size(), 0u);
  const auto view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  GridLookup lookup;
  ASSERT_TRUE(lookup.Init(view->grid).ok());
  std::vector<int32_t> coords[3];
  for (int d = 0; d < 3; ++d) coords[d] = AdversarialPositions(g.dim[d], rng);
  const size_t n = std::max({coords[0].size(), coords[1].size(), coords[2].size()}) * 3;
  for (size_t i = 0; i < n; ++i) {
    const int32_t pos[3] = {coords[0][i % coords[0].size()],
                            coords[1][(i * 7 + 1) % coords[1].size()],
                            coords[2][(i * 13 + 2) % coords[2].size()]};
    int32_t ref[3], fast[3], parts[3];
    lookup.Interpolate<Loader>(pos, ref);
    lookup.Lookup(pos, fast);
    GridLookup::Partial s;
    lookup.Begin(pos, &s);
    lookup.AccumulateZ0(&s);
    lookup.FinishZ1(s, parts);
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(fast[c], ref[c]) << "type " << int(g.type) << " c " << c;
      ASSERT_EQ(parts[c], ref[c]) << "type " << int(g.type) << " c " << c;
    }
    ++*points;
  }
}

TEST(HotPathReference, GridKernelsAndPartsEqualTheReference) {
  std::mt19937_64 rng(102);
  uint64_t points = 0;
  for (int t = 0; t < 40; ++t) {
    // Random tables (every cell parity, so int16 rows start on either half of a word) and
    // tables at the value limits.
    CheckGrid<LoadInt16>(testing::RandomGrid(rng, table::ElementType::kInt16, 9, 200000, 65536),
                         rng, &points);
    CheckGrid<LoadInt32>(testing::RandomGrid(rng, table::ElementType::kInt32, 9, 200000, 65536),
                         rng, &points);
    CheckGrid<LoadFloat32>(testing::RandomGrid(rng, table::ElementType::kFloat32, 9, 200000, 65536),
                           rng, &points);
    CheckGrid<LoadInt16>(ExtremeGrid(rng, table::ElementType::kInt16), rng, &points);
    CheckGrid<LoadInt32>(ExtremeGrid(rng, table::ElementType::kInt32), rng, &points);
    CheckGrid<LoadFloat32>(ExtremeGrid(rng, table::ElementType::kFloat32), rng, &points);
    if (HasFatalFailure()) return;
  }
  std::printf("[ metric ] grid kernels and three-part lookup == reference on %llu points\n",
              static_cast<unsigned long long>(points));
}

TEST(HotPathReference, AxisLookupEqualsReference) {
  std::mt19937_64 rng(103);
  uint64_t n = 0;
  const table::ElementType types[] = {table::ElementType::kInt16, table::ElementType::kInt32,
                                      table::ElementType::kFloat32};
  for (int t = 0; t < 600; ++t) {
    const table::ElementType type = types[t % 3];
    table::Axis1dSpec a;
    a.frac_bits = type == table::ElementType::kFloat32 ? 0 : static_cast<uint8_t>(rng() % 9);
    a.dim = RandomDimension(rng, 64);
    const uint32_t count = a.dim.nodes;
    std::vector<int16_t> f16(count), r16(count);
    std::vector<int32_t> f32i(count), r32i(count);
    std::vector<float> ff(count), rf(count);
    const bool extreme = t % 5 == 0;
    for (uint32_t i = 0; i < count; ++i) {
      const int64_t lim32 = int64_t{table::kMaxCorrectionSteps} << a.frac_bits;
      const int64_t lim = type == table::ElementType::kInt16 ? 32767 : lim32;
      auto value = [&] {
        return extreme ? ((rng() & 1) ? lim : -lim)
                       : static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * lim + 1)) - lim;
      };
      f16[i] = static_cast<int16_t>(value());
      r16[i] = static_cast<int16_t>(value());
      f32i[i] = static_cast<int32_t>(value());
      r32i[i] = static_cast<int32_t>(value());
      ff[i] = static_cast<float>(value()) / 256.0f;
      rf[i] = static_cast<float>(value()) / 256.0f;
    }
    a.forward = {type, f16.data(), f32i.data(), ff.data()};
    a.has_reverse = (t & 1) != 0;
    a.reverse = {type, r16.data(), r32i.data(), rf.data()};
    a.backlash_q8 = static_cast<int32_t>(rng() % 2001) - 1000;
    table::ImageSpec s;
    s.axis_count = 1;
    s.axes[0] = testing::LinearAxis('X');
    s.axis1d_count = 1;
    s.axis1d[0] = a;
    const auto size = table::ImageSize(s);
    ASSERT_TRUE(size.ok());
    testing::AlignedBytes img(*size);
    ASSERT_TRUE(table::WriteImage(s, img.data(), img.size()).ok());
    const auto view = table::ParseImage(img.data(), img.size());
    ASSERT_TRUE(view.ok()) << view.status().name();
    AxisLookup lookup;
    ASSERT_TRUE(lookup.Init(view->axis1d[0]).ok());
    for (int32_t p : AdversarialPositions(a.dim, rng)) {
      for (bool rev : {false, true}) {
        ASSERT_EQ(lookup.Lookup(p, rev), lookup.LookupReference(p, rev))
            << "type " << int(type) << " pos " << p << " reverse " << rev;
        ++n;
      }
    }
  }
  std::printf("[ metric ] AxisLookup::Lookup == reference on %llu lookups\n",
              static_cast<unsigned long long>(n));
}

// Random drive timings (step/dir and quadrature; slow and fast drives; hold and setup from zero to
// several ticks) and target sequences (standstill, creeping, bursts beyond one tick's capacity,
// reversals every tick, long pauses that reach the far-past floor of the time arithmetic).
TEST(HotPathReference, StepGeneratorPlansEqualTheInt64Reference) {
  std::mt19937_64 rng(104);
  uint64_t ticks = 0, pulses = 0, reversals = 0;
  for (int c = 0; c < 300; ++c) {
    AxisConfig ax;
    ax.output_format = (rng() % 3 == 0) ? PulseFormat::kQuadrature : PulseFormat::kStepDir;
    const uint32_t tick_hz = 1000 + static_cast<uint32_t>(rng() % 199001);
    const uint32_t clock =
        std::max<uint32_t>(tick_hz * 100u, 1000000u + static_cast<uint32_t>(rng() % 4) * 56666666u);
    ax.drive.pulse_width_ns = static_cast<uint32_t>(rng() % 5000);
    ax.drive.step_space_ns = static_cast<uint32_t>(rng() % 5000);
    ax.drive.dir_setup_ns = static_cast<uint32_t>(rng() % (c % 4 == 0 ? 3000000 : 20000));
    ax.drive.dir_hold_ns = static_cast<uint32_t>(rng() % (c % 4 == 1 ? 3000000 : 20000));
    ax.drive.max_rate_hz = 1000 + static_cast<uint32_t>(rng() % 4000000);
    StepGenerator fast;
    StepGeneratorReference ref;
    const Status sf = fast.Configure(ax, tick_hz, clock);
    const Status sr = ref.Configure(ax, tick_hz, clock);
    ASSERT_EQ(sf.ok(), sr.ok());
    if (!sf.ok()) continue;
    const int32_t start = static_cast<int32_t>(rng());
    fast.Reset(start);
    ref.Reset(start);
    int32_t target = start;
    const uint32_t cap = fast.max_pulses_per_tick();
    for (int i = 0; i < 3000; ++i) {
      switch ((i / 100 + c) % 6) {
        case 0:
          break;  // standstill
        case 1:
          target += static_cast<int32_t>(rng() % 3) - 1;
          break;
        case 2:
          target += static_cast<int32_t>(rng() % (2 * cap + 2));
          break;
        case 3:
          target +=
              (i & 1) ? 1 + static_cast<int32_t>(rng() % 3) : -1 - static_cast<int32_t>(rng() % 3);
          break;
        case 4:
          if (i % 100 == 0) target += static_cast<int32_t>(rng() % 20001) - 10000;
          break;
        default:
          if (i % 37 == 0) target -= static_cast<int32_t>(rng() % 5);
          break;
      }
      PulsePlan pf;
      const uint32_t left = fast.PlanTick(target, &pf);
      const PulsePlan pr = ref.Plan(target);
      ASSERT_EQ(pf.count, pr.count) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.negative, pr.negative) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.dir_change, pr.dir_change) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.dir_edge, pr.dir_edge) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.first_rise, pr.first_rise) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.period, pr.period) << "config " << c << " tick " << i;
      ASSERT_EQ(pf.width, pr.width) << "config " << c << " tick " << i;
      ASSERT_EQ(fast.position(), ref.position());
      const int32_t owed = fast.backlog(target);
      ASSERT_EQ(left, static_cast<uint32_t>(owed < 0 ? -static_cast<int64_t>(owed) : owed));
      ++ticks;
      pulses += pf.count;
      reversals += pf.dir_change ? 1 : 0;
    }
    // A pause long enough for the last pulse to fall below the far-past floor (2^30 pulse-clock
    // units), then a reversal: the floor must not change the plan.
    const uint32_t idle_ticks = (1u << 30) / fast.tick_length() + 2;
    if (idle_ticks < 400000) {
      for (uint32_t i = 0; i < idle_ticks; ++i) {
        PulsePlan pf;
        fast.PlanTick(target, &pf);
        ref.Plan(target);
      }
      target -= 3;
      PulsePlan pf;
      fast.PlanTick(target, &pf);
      const PulsePlan pr = ref.Plan(target);
      ASSERT_EQ(pf.dir_edge, pr.dir_edge);
      ASSERT_EQ(pf.first_rise, pr.first_rise);
      ASSERT_EQ(pf.count, pr.count);
    }
  }
  EXPECT_GT(pulses, 100000u);
  EXPECT_GT(reversals, 1000u);
  std::printf(
      "[ metric ] StepGenerator == int64 reference on %llu ticks (%llu pulses, %llu "
      "reversals)\n",
      static_cast<unsigned long long>(ticks), static_cast<unsigned long long>(pulses),
      static_cast<unsigned long long>(reversals));
}

TEST(HotPathReference, StepGeneratorRefusesTimesBeyondItsArithmetic) {
  AxisConfig ax;
  ax.drive.dir_hold_ns = 600000000;  // 0.6 s at 1 GHz: 6e8 > 2^29 pulse-clock units
  StepGenerator gen;
  EXPECT_EQ(gen.Configure(ax, 50000, 1000000000).error(), Error::kConfigInvalid);
  ax.drive.dir_hold_ns = 500000000;
  EXPECT_TRUE(gen.Configure(ax, 50000, 1000000000).ok());
  ax.drive.dir_setup_ns = 600000000;
  EXPECT_EQ(gen.Configure(ax, 50000, 1000000000).error(), Error::kConfigInvalid);
}

TEST(HotPathReference, LimiterStepEqualsReference) {
  std::mt19937_64 rng(105);
  uint64_t steps = 0;
  for (int c = 0; c < 400; ++c) {
    const uint32_t tick_hz = 1000 + static_cast<uint32_t>(rng() % 199001);
    const uint32_t rate = 1 + static_cast<uint32_t>(rng() % 100000);
    const uint32_t accel = 1 + static_cast<uint32_t>(rng() % 50000000);
    const auto made = CorrectionLimiter::MakeParams(tick_hz, rate, accel);
    if (!made.ok()) continue;
    LimiterParams params = *made;
    CorrectionLimiter lim(params);
    int64_t pos = 0;
    int32_t k = 0;
    int64_t target = 0;
    for (int i = 0; i < 4000; ++i) {
      if (i % 300 == 0 || rng() % 97 == 0) {
        // Targets up to the largest correction (65536 steps), sub-step residues, and zero.
        switch (rng() % 4) {
          case 0:
            target = static_cast<int64_t>(rng() % (2 * (uint64_t{65536} << 32) + 1)) -
                     (int64_t{65536} << 32);
            break;
          case 1:
            target = pos + static_cast<int64_t>(rng() % 2001) - 1000;
            break;
          case 2:
            target = 0;
            break;
          default:
            target = -target;
            break;
        }
      }
      if (i == 2000) {  // a smaller velocity limit while moving (set_params)
        params.max_k = std::max<uint32_t>(1, params.max_k / 3);
        lim.set_params(params);
      }
      const int64_t got = lim.Step(target);
      const int64_t want = LimiterStepReference(params, pos, k, target);
      ASSERT_EQ(got, want) << "config " << c << " tick " << i;
      ASSERT_EQ(lim.position_q32(), pos);
      ASSERT_EQ(lim.velocity_index(), k);
      ++steps;
    }
  }
  std::printf("[ metric ] CorrectionLimiter::Step == reference on %llu ticks\n",
              static_cast<unsigned long long>(steps));
}

TEST(HotPathReference, WrapTrackerForDeltasUpToThePeriod) {
  std::mt19937_64 rng(106);
  for (int t = 0; t < 200; ++t) {
    const uint32_t period =
        t == 0 ? table::kMaxExtentSteps
               : 1 + static_cast<uint32_t>((rng() >> (rng() % 60)) % table::kMaxExtentSteps);
    const int32_t origin = static_cast<int32_t>(
        INT32_MIN + static_cast<int64_t>(rng() % (uint64_t{UINT32_MAX} - period + 1)));
    int64_t abs_pos = static_cast<int32_t>(rng());
    WrapTracker w;
    w.Init(static_cast<int32_t>(abs_pos), origin, period);
    for (int i = 0; i < 2000; ++i) {
      // |delta| < period, up to the int32 range.
      const uint64_t span = std::min<uint64_t>(period - 1u, 0x7FFFFFFFu);
      int32_t d = static_cast<int32_t>(rng() % (span + 1));
      if (rng() & 1) d = -d;
      abs_pos += d;
      const int32_t got = w.Update(d);
      int64_t expect = (abs_pos - origin) % period;
      if (expect < 0) expect += period;
      ASSERT_EQ(got, expect + origin) << "period " << period << " step " << i;
    }
  }
}

}  // namespace
}  // namespace volcomp
