// StepOutput: one generator per configured axis, backlog statistics and overruns, Plan() and
// PlanEach() giving the same plans; values worked by hand (1 kHz tick, 1 MHz pulse clock: a tick
// is 1000 units and carries 100 pulses at the drive's 10-unit minimum period).
#include "volcomp/output/step_output.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace volcomp {
namespace {

BoardConfig HandConfig(uint8_t axes) {
  BoardConfig c = DefaultBoardConfig();
  c.axis_count = axes;
  c.tick_hz = 1000;
  c.pulse_clock_hz = 1000000;
  for (uint8_t a = 0; a < axes; ++a) {
    c.axis[a].output_format = PulseFormat::kStepDir;
    c.axis[a].drive = {2000, 3000, 4000, 6000, 100000};  // width, space, setup, hold, rate
  }
  return c;
}

TEST(StepOutput, PlansEveryAxisAndCountsTheBacklog) {
  StepOutput out;
  ASSERT_TRUE(out.Configure(HandConfig(2)).ok());
  EXPECT_EQ(out.axis_count(), 2);
  const int32_t targets[2] = {3, -250};
  PulsePlan plans[2];

  out.Plan(targets, plans);
  EXPECT_EQ(plans[0].count, 3u);
  EXPECT_EQ(plans[0].period, 333u);
  EXPECT_FALSE(plans[0].negative);
  // Axis 1 reverses from the power-up direction (positive): at once, pulses after the setup time.
  EXPECT_TRUE(plans[1].dir_change);
  EXPECT_EQ(plans[1].dir_edge, 0u);
  EXPECT_EQ(plans[1].first_rise, 4u);
  EXPECT_EQ(plans[1].count, 100u);
  EXPECT_TRUE(plans[1].negative);
  EXPECT_EQ(out.position(0), 3);
  EXPECT_EQ(out.position(1), -100);
  EXPECT_EQ(out.backlog(1, targets[1]), -150);
  EXPECT_EQ(out.max_backlog(0), 0u);
  EXPECT_EQ(out.max_backlog(1), 150u);
  EXPECT_EQ(out.overruns(), 1u);  // 150 owed > the 100 a tick carries

  out.Plan(targets, plans);
  EXPECT_EQ(plans[0].count, 0u);
  EXPECT_EQ(plans[1].count, 100u);
  EXPECT_FALSE(plans[1].dir_change);
  EXPECT_EQ(out.max_backlog(1), 150u);  // 50 owed now: the maximum stays
  EXPECT_EQ(out.overruns(), 1u);

  out.Plan(targets, plans);
  EXPECT_EQ(plans[1].count, 50u);
  EXPECT_EQ(out.position(1), -250);
  EXPECT_EQ(out.backlog(1, targets[1]), 0);

  // Configure() restarts positions and statistics.
  ASSERT_TRUE(out.Configure(HandConfig(2)).ok());
  EXPECT_EQ(out.position(1), 0);
  EXPECT_EQ(out.max_backlog(1), 0u);
  EXPECT_EQ(out.overruns(), 0u);
}

TEST(StepOutput, PlanEachHandsOverThePlansOfPlanInAxisOrder) {
  StepOutput a, b;
  ASSERT_TRUE(a.Configure(HandConfig(3)).ok());
  ASSERT_TRUE(b.Configure(HandConfig(3)).ok());
  const int32_t script[4][3] = {{5, -7, 0}, {330, -7, 2}, {330, 20, -40}, {330, 0, 0}};
  for (const auto& targets : script) {
    PulsePlan plans[3];
    a.Plan(targets, plans);
    std::vector<uint32_t> order;
    b.PlanEach(targets, [&](uint32_t axis, const PulsePlan& p) {
      order.push_back(axis);
      EXPECT_EQ(p.count, plans[axis].count);
      EXPECT_EQ(p.negative, plans[axis].negative);
      EXPECT_EQ(p.dir_change, plans[axis].dir_change);
      EXPECT_EQ(p.dir_edge, plans[axis].dir_edge);
      EXPECT_EQ(p.first_rise, plans[axis].first_rise);
      EXPECT_EQ(p.period, plans[axis].period);
      EXPECT_EQ(p.width, plans[axis].width);
    });
    EXPECT_EQ(order, (std::vector<uint32_t>{0, 1, 2}));
    for (uint8_t x = 0; x < 3; ++x) EXPECT_EQ(a.position(x), b.position(x));
  }
  EXPECT_EQ(a.overruns(), b.overruns());
  // Axis 0's jump to 330 leaves 225, then 125 steps owed: above one tick's 100 twice.
  EXPECT_EQ(a.overruns(), 2u);
  EXPECT_EQ(a.max_backlog(0), 225u);
  EXPECT_EQ(a.position(0), 305);
}

TEST(StepOutput, RefusesAndKeepsNoAxes) {
  StepOutput out;
  BoardConfig c = HandConfig(2);
  c.axis[1].drive.max_rate_hz = 999;  // a step period longer than the tick
  EXPECT_EQ(out.Configure(c).error(), Error::kConfigInvalid);
  EXPECT_EQ(out.axis_count(), 0);
  c = HandConfig(2);
  c.axis_count = 7;
  EXPECT_EQ(out.Configure(c).error(), Error::kConfigInvalid);
  EXPECT_EQ(out.axis_count(), 0);
}

}  // namespace
}  // namespace volcomp
