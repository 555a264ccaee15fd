// The LinuxCNC components' logic without LinuxCNC: the board's output waveform sampled at the base
// period loses no pulse and keeps the drive's direction rules (checked by a drive counter written
// here), and the native compensator applies the table (checked against the independent double
// trilinear reference), ramps out when disabled, clamps visibly and refuses a table for other
// axes without losing the active one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "board/hal_step_io.hpp"
#include "native/native_compensator.hpp"
#include "test_tables.hpp"
#include "volcomp/step_generator.hpp"

namespace volcomp::linuxcnc {
namespace {

// A step/dir drive sampling its inputs once per base period: counts a rising STEP edge up while
// DIR is low, down while high; flags a DIR change while STEP is high or in the sample of a rise.
struct SampledDrive {
  int64_t count = 0;
  bool step = false, dir = false;
  int violations = 0;
  void Sample(bool s, bool d) {
    if (d != dir && (step || s)) ++violations;
    if (s && !step) count += d ? -1 : 1;
    step = s;
    dir = d;
  }
};

TEST(LinuxcncBoardIo, SampledOutputLosesNoPulse) {
  constexpr uint32_t kPeriodNs = 20000, kTickHz = 1000000000u / (2 * kPeriodNs);
  AxisConfig axis;
  axis.drive = {kPeriodNs, kPeriodNs, kPeriodNs, kPeriodNs, kTickHz};
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(axis, kTickHz, 1000000000u).ok());
  HalStepIo io;
  io.Configure(true, true);
  SampledDrive drive;
  drive.dir = false;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> move(-1, 1);
  int32_t target = 0;
  int64_t now = 0;
  for (int tick = 0; tick < 200000; ++tick) {
    // A random walk with runs, reversals and pauses; at most one step per tick (the tick rate is
    // the drive's maximum rate), often less.
    if (tick % 7 != 0) target += move(rng);
    PulsePlan plans[HalStepIo::kAxes];
    io.BeginTick(now);
    plans[0] = gen.Plan(target);
    io.Apply(plans);
    for (int p = 0; p < 2; ++p, now += kPeriodNs) {
      bool step[HalStepIo::kAxes], dir[HalStepIo::kAxes];
      io.Render(now, step, dir);
      drive.Sample(step[0], dir[0]);
    }
  }
  for (int tick = 0; tick < 1000; ++tick, now += 2 * kPeriodNs) {  // drain the backlog
    PulsePlan plans[HalStepIo::kAxes];
    io.BeginTick(now);
    plans[0] = gen.Plan(target);
    io.Apply(plans);
    bool step[HalStepIo::kAxes], dir[HalStepIo::kAxes];
    io.Render(now, step, dir);
    drive.Sample(step[0], dir[0]);
    io.Render(now + kPeriodNs, step, dir);
    drive.Sample(step[0], dir[0]);
  }
  EXPECT_EQ(gen.position(), target);
  EXPECT_EQ(drive.count, target);
  EXPECT_EQ(drive.violations, 0);
  EXPECT_EQ(io.queue_overflows(), 0u);
  EXPECT_GT(io.rendered_pulses(0), 10000);
}

// 1 um per step; positions in mm.
constexpr double kMmPerStep = 0.001;

testing::GridCase Grid(uint64_t seed, double amplitude_steps) {
  std::mt19937_64 rng(seed);
  testing::GridCase g =
      testing::RandomGrid(rng, table::ElementType::kInt16, 5, 1000, amplitude_steps);
  for (auto& d : g.dim) d.origin_steps = 0;
  return g;
}

std::vector<uint8_t> Bytes(const testing::AlignedBytes& a) {
  return std::vector<uint8_t>(a.data(), a.data() + a.size());
}

TEST(LinuxcncNative, AppliesTheTableAndRampsOut) {
  const testing::GridCase g = Grid(11, 40.0);
  NativeCompensator c;
  ASSERT_TRUE(c.Load(Bytes(testing::WriteGridImage(g)), 1000, NativeLimits()).ok());
  EXPECT_EQ(c.axis_count(), 3u);
  const int32_t at[3] = {static_cast<int32_t>(g.dim[0].spacing_steps / 3),
                         static_cast<int32_t>(g.dim[1].spacing_steps * 1.5),
                         static_cast<int32_t>(g.dim[2].spacing_steps / 2)};
  const double pos[3] = {at[0] * kMmPerStep, at[1] * kMmPerStep, at[2] * kMmPerStep};
  double corr[3];
  for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr);  // 2 s at 1 kHz: settled
  EXPECT_TRUE(c.engaged());
  EXPECT_FALSE(c.clamped());
  for (int a = 0; a < 3; ++a) {
    // The fixed-point lookup is within 1 LSB (1/256 step) of the exact value.
    EXPECT_NEAR(corr[a] / kMmPerStep, testing::ExactTrilinear(g, at, a), 1.0 / 256 + 1e-9) << a;
  }
  for (int i = 0; i < 2000; ++i) c.Tick(pos, false, true, corr);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(corr[a], 0.0) << a;
  EXPECT_FALSE(c.engaged());
}

TEST(LinuxcncNative, ClampsVisiblyAndKeepsTheActiveTable) {
  const testing::GridCase g = Grid(12, 200.0);
  NativeCompensator c;
  NativeLimits limits;
  limits.max_correction_steps = 5;
  ASSERT_TRUE(c.Load(Bytes(testing::WriteGridImage(g)), 1000, limits).ok());
  const double pos[3] = {0.0, 0.0, 0.0};
  double corr[3];
  for (int i = 0; i < 2000; ++i) c.Tick(pos, true, true, corr);
  bool any_over = false;
  const int32_t at[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(std::fabs(corr[a]), 5 * kMmPerStep + 1e-12) << a;
    any_over |= std::fabs(testing::ExactTrilinear(g, at, a)) > 5.0;
  }
  EXPECT_EQ(c.clamped(), any_over);
  // A table for another step size is refused; the active one stays.
  const uint32_t crc = c.table_crc32();
  // A valid image whose X has 2 um steps.
  testing::GridCase other = Grid(13, 10.0);
  std::vector<uint8_t> wrong;
  {
    table::ImageSpec spec;
    table::GridSpec grid;
    grid.frac_bits = other.frac_bits;
    for (int d = 0; d < 3; ++d) grid.dim[d] = other.dim[d];
    grid.values.type = other.type;
    grid.values.i16 = other.i16.data();
    spec.axis_count = 3;
    spec.axes[0] = testing::LinearAxis('X', 2000000);
    spec.axes[1] = testing::LinearAxis('Y');
    spec.axes[2] = testing::LinearAxis('Z');
    spec.grid = &grid;
    testing::AlignedBytes out(*table::ImageSize(spec));
    ASSERT_TRUE(table::WriteImage(spec, out.data(), out.size()).ok());
    wrong = Bytes(out);
  }
  EXPECT_EQ(c.Load(wrong, 1000, limits).error(), Error::kConfigAxisMismatch);
  EXPECT_EQ(c.table_crc32(), crc);
  c.Tick(pos, true, true, corr);
  EXPECT_TRUE(c.engaged());
}

}  // namespace
}  // namespace volcomp::linuxcnc
