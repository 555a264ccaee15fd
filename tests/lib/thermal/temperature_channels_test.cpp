// Temperature channel supervision against its contract (temperature_channels.hpp, docs/thermal.md):
// the figures are worked by hand from the documented limits (1 K/s + 0.25 K slack, 1.5 s timeout,
// three good readings to recover), not taken from the code.
#include "volcomp/thermal/temperature_channels.hpp"

#include <gtest/gtest.h>

namespace volcomp::thermal {
namespace {

ChannelConfig CanChannel() {
  ChannelConfig c;
  c.source = ChannelSource::kCanObject;
  return c;
}

class ChannelsTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(ch_.Configure(0, CanChannel(), 0).ok()); }
  void Read(int16_t v, uint32_t t) { ASSERT_TRUE(ch_.Reading(0, v, t).ok()); }
  TemperatureChannels ch_;
};

TEST(ChannelConfigTest, ChecksEveryLimit) {
  EXPECT_TRUE(ValidateChannelConfig(ChannelConfig()).ok());  // unused: nothing else checked
  EXPECT_TRUE(ValidateChannelConfig(CanChannel()).ok());
  auto with = [](auto change) {
    ChannelConfig c = CanChannel();
    change(c);
    return ValidateChannelConfig(c).ok();
  };
  EXPECT_FALSE(with([](ChannelConfig& c) { c.timeout_ms = 99; }));
  EXPECT_TRUE(with([](ChannelConfig& c) { c.timeout_ms = 100; }));
  EXPECT_TRUE(with([](ChannelConfig& c) { c.timeout_ms = 60000; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.timeout_ms = 60001; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.low_cC = c.high_cC; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.low_cC = kNoReading_cC; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.max_rate_cC_s = 0; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.stuck_readings = 1; }));
  EXPECT_TRUE(with([](ChannelConfig& c) { c.stuck_readings = 2; }));
  EXPECT_FALSE(with([](ChannelConfig& c) { c.source = static_cast<ChannelSource>(6); }));
}

TEST(ChannelsConfigureTest, RefusesAndKeepsTheChannel) {
  TemperatureChannels ch;
  ASSERT_TRUE(ch.Configure(2, CanChannel(), 0).ok());
  ASSERT_TRUE(ch.Reading(2, 2150, 10).ok());
  ChannelConfig bad = CanChannel();
  bad.high_cC = bad.low_cC;
  EXPECT_EQ(ch.Configure(2, bad, 20).error(), Error::kInvalidArgument);
  EXPECT_EQ(ch.Configure(kMaxChannels, CanChannel(), 20).error(), Error::kInvalidArgument);
  EXPECT_EQ(ch.state(2), ChannelState::kValid);
  EXPECT_EQ(ch.value_cC(2), 2150);
}

TEST(ChannelsConfigureTest, UnusedChannelsRefuseReadings) {
  TemperatureChannels ch;
  EXPECT_EQ(ch.state(0), ChannelState::kUnused);
  EXPECT_EQ(ch.Reading(0, 2000, 0).error(), Error::kNotReady);
  EXPECT_EQ(ch.Reading(kMaxChannels, 2000, 0).error(), Error::kNotFound);
  ch.Supervise(1000000);  // unused channels never go stale
  EXPECT_EQ(ch.state(0), ChannelState::kUnused);
  EXPECT_EQ(ch.fault_mask(), 0);
  EXPECT_EQ(ch.TakeEvents().faulted, 0);
}

TEST_F(ChannelsTest, FirstReadingInRangeIsTakenAtOnce) {
  EXPECT_EQ(ch_.state(0), ChannelState::kWaiting);
  Read(2037, 5);
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  EXPECT_EQ(ch_.value_cC(0), 2037);
  EXPECT_EQ(ch_.valid_mask(), 0x01);
}

TEST_F(ChannelsTest, GoesStaleOneMillisecondAfterItsTimeoutAndHoldsItsValue) {
  Read(2100, 1000);
  ch_.Supervise(2500);  // exactly 1500 ms: still valid
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  ch_.Supervise(2501);
  EXPECT_EQ(ch_.state(0), ChannelState::kStale);
  EXPECT_EQ(ch_.value_cC(0), 2100);
  EXPECT_EQ(ch_.fault_mask(), 0x01);
  EXPECT_EQ(ch_.fault_count(0), 1);
  const ChannelEvents e = ch_.TakeEvents();
  EXPECT_EQ(e.faulted, 0x01);
  EXPECT_EQ(e.recovered, 0);
  ch_.Supervise(9000);  // still stale: no second onset
  EXPECT_EQ(ch_.TakeEvents().faulted, 0);
  EXPECT_EQ(ch_.fault_count(0), 1);
}

TEST_F(ChannelsTest, AOneHertzSourceThatStopsIsDetectedWithinTwoSeconds) {
  uint32_t t = 0;
  for (; t <= 10000; t += 1000) Read(2000, t);  // last reading at 10 s, the source then stops
  const uint32_t stopped_ms = 10000 + 1000;     // the reading that did not come
  uint32_t detected_ms = 0;
  for (uint32_t now = 10000; now < 20000 && detected_ms == 0; now += 100) {
    ch_.Supervise(now);
    if (ch_.state(0) == ChannelState::kStale) detected_ms = now;
  }
  EXPECT_EQ(detected_ms, 11600u);  // 1500 ms timeout, supervised every 100 ms
  EXPECT_LE(detected_ms - stopped_ms, 2000u);
}

TEST_F(ChannelsTest, ASourceThatNeverReportsGoesStale) {
  ch_.Supervise(1500);
  EXPECT_EQ(ch_.state(0), ChannelState::kWaiting);
  ch_.Supervise(1501);
  EXPECT_EQ(ch_.state(0), ChannelState::kStale);
  EXPECT_EQ(ch_.TakeEvents().faulted, 0x01);
}

TEST_F(ChannelsTest, OpenOrShortedSensorIsOutOfRangeAndTheLimitsAreInclusive) {
  Read(9000, 0);  // +90 C, the default high limit: in range
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  Read(kNoReading_cC, 500);
  EXPECT_EQ(ch_.state(0), ChannelState::kOutOfRange);
  EXPECT_EQ(ch_.value_cC(0), 9000);
  EXPECT_EQ(ch_.last_reading_cC(0), kNoReading_cC);
  Read(9001, 1000);
  EXPECT_EQ(ch_.state(0), ChannelState::kOutOfRange);
  EXPECT_EQ(ch_.fault_count(0), 1);  // one fault, two bad readings

  TemperatureChannels low;
  ASSERT_TRUE(low.Configure(1, CanChannel(), 0).ok());
  ASSERT_TRUE(low.Reading(1, -2001, 0).ok());  // below -20 C on the first reading
  EXPECT_EQ(low.state(1), ChannelState::kOutOfRange);
  EXPECT_EQ(low.value_cC(1), 0);
}

TEST_F(ChannelsTest, RateLimitIsOneKelvinPerSecondPlusSlack) {
  Read(2000, 0);
  Read(2125, 1000);  // 100 cC/s * 1 s + 25 cC slack: the most allowed
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  Read(2251, 2000);  // 126 cC in 1 s
  EXPECT_EQ(ch_.state(0), ChannelState::kImplausibleRate);
  EXPECT_EQ(ch_.value_cC(0), 2125);

  TemperatureChannels fast;  // two readings 10 ms apart may differ by 26 cC (1 + 25), no more
  ASSERT_TRUE(fast.Configure(0, CanChannel(), 0).ok());
  ASSERT_TRUE(fast.Reading(0, 2000, 0).ok());
  ASSERT_TRUE(fast.Reading(0, 1974, 10).ok());
  EXPECT_EQ(fast.state(0), ChannelState::kValid);
  ASSERT_TRUE(fast.Reading(0, 2001, 20).ok());
  EXPECT_EQ(fast.state(0), ChannelState::kImplausibleRate);
}

TEST_F(ChannelsTest, ASpikeNeverEntersTheValue) {
  for (uint32_t t = 0; t < 5000; t += 1000) Read(2000, t);
  Read(6000, 5000);  // one bad reading
  Read(2001, 6000);  // back: a jump again from the spike
  EXPECT_EQ(ch_.state(0), ChannelState::kImplausibleRate);
  Read(2002, 7000);
  Read(2003, 8000);
  EXPECT_EQ(ch_.state(0), ChannelState::kImplausibleRate);  // two good readings: not yet
  EXPECT_EQ(ch_.value_cC(0), 2000);
  Read(2004, 9000);  // the third
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  EXPECT_EQ(ch_.value_cC(0), 2004);
  const ChannelEvents e = ch_.TakeEvents();
  EXPECT_EQ(e.faulted, 0x01);
  EXPECT_EQ(e.recovered, 0x01);
  EXPECT_EQ(ch_.fault_count(0), 1);
}

TEST_F(ChannelsTest, ASteadyStepIsTakenAfterThreeReadings) {
  Read(2000, 0);
  Read(3000, 1000);  // a replaced sensor reads 10 K higher
  EXPECT_EQ(ch_.state(0), ChannelState::kImplausibleRate);
  Read(3000, 2000);
  Read(3001, 3000);
  Read(3000, 4000);
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  EXPECT_EQ(ch_.value_cC(0), 3000);
}

TEST_F(ChannelsTest, AStaleChannelRecoversAfterThreeReadings) {
  Read(2000, 0);
  ch_.Supervise(5000);
  ASSERT_EQ(ch_.state(0), ChannelState::kStale);
  ch_.TakeEvents();
  Read(2050, 60000);  // after a minute: 0.5 K is plausible
  Read(2050, 61000);
  EXPECT_EQ(ch_.state(0), ChannelState::kStale);
  ch_.Supervise(61500);  // readings keep coming: no new onset
  Read(2051, 62000);
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  EXPECT_EQ(ch_.value_cC(0), 2051);
  EXPECT_EQ(ch_.TakeEvents().recovered, 0x01);
  EXPECT_EQ(ch_.fault_count(0), 1);
}

TEST(ChannelsStuckTest, FiveEqualReadingsInARowAreAFrozenSource) {
  TemperatureChannels ch;
  ChannelConfig c = CanChannel();
  c.source = ChannelSource::kBoardNtc;
  c.stuck_readings = 5;
  ASSERT_TRUE(ch.Configure(3, c, 0).ok());
  ASSERT_TRUE(ch.Reading(3, 2000, 0).ok());
  ASSERT_TRUE(ch.Reading(3, 2001, 100).ok());  // noise: the run restarts
  for (uint32_t t = 200; t <= 500; t += 100) ASSERT_TRUE(ch.Reading(3, 2003, t).ok());
  EXPECT_EQ(ch.state(3), ChannelState::kValid);  // four equal readings
  ASSERT_TRUE(ch.Reading(3, 2003, 600).ok());    // the fifth
  EXPECT_EQ(ch.state(3), ChannelState::kStuck);
  EXPECT_EQ(ch.TakeEvents().faulted, 0x08);
  ASSERT_TRUE(ch.Reading(3, 2004, 700).ok());
  ASSERT_TRUE(ch.Reading(3, 2002, 800).ok());
  ASSERT_TRUE(ch.Reading(3, 2003, 900).ok());
  EXPECT_EQ(ch.state(3), ChannelState::kValid);

  TemperatureChannels off;  // stuck_readings 0: a PLC writing the same value is fine
  ASSERT_TRUE(off.Configure(0, CanChannel(), 0).ok());
  for (uint32_t t = 0; t < 300000; t += 1000) ASSERT_TRUE(off.Reading(0, 2000, t).ok());
  EXPECT_EQ(off.state(0), ChannelState::kValid);
}

TEST_F(ChannelsTest, TimesWrapAroundTheClock) {
  const uint32_t before_wrap = 0xFFFFFF00u;
  ASSERT_TRUE(ch_.Configure(0, CanChannel(), before_wrap).ok());
  Read(2000, before_wrap);
  Read(2075, before_wrap + 512);  // 512 ms across the wrap: 51 + 25 cC allowed
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  ch_.Supervise(before_wrap + 512 + 1500);
  EXPECT_EQ(ch_.state(0), ChannelState::kValid);
  ch_.Supervise(before_wrap + 512 + 1501);
  EXPECT_EQ(ch_.state(0), ChannelState::kStale);
}

TEST_F(ChannelsTest, ReconfiguringRestartsTheChannel) {
  Read(kNoReading_cC, 0);
  ASSERT_EQ(ch_.fault_count(0), 1);
  ASSERT_TRUE(ch_.Configure(0, CanChannel(), 100).ok());
  EXPECT_EQ(ch_.state(0), ChannelState::kWaiting);
  EXPECT_EQ(ch_.fault_count(0), 0);
  EXPECT_EQ(ch_.TakeEvents().faulted, 0);  // the old channel's event went with it
  ASSERT_TRUE(ch_.Configure(0, ChannelConfig(), 200).ok());
  EXPECT_EQ(ch_.state(0), ChannelState::kUnused);
}

TEST(ChannelStateNameTest, NamesEveryState) {
  EXPECT_STREQ(ChannelStateName(ChannelState::kStale), "stale");
  EXPECT_STREQ(ChannelStateName(ChannelState::kImplausibleRate), "implausible rate");
  EXPECT_STREQ(ChannelStateName(static_cast<ChannelState>(99)), "unknown");
}

}  // namespace
}  // namespace volcomp::thermal
