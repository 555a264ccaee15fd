// MockFlash (the NOR model the store tests and the fault campaign rely on: erase to 0xFF, program
// clears bits only, injected power loss tears one operation and stops the rest), MockCan and
// MockTickTimer, with the timeline they record.
#include "volcomp/hal/mock/mock_devices.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace volcomp::hal::mock {
namespace {

TEST(MockFlash, EraseSetsOnesAndProgramOnlyClearsBits) {
  MockClock clock;
  Timeline timeline;
  MockFlash flash(4096, 1024, 8, &clock, &timeline);
  EXPECT_EQ(flash.size(), 4096u);
  EXPECT_EQ(flash.Map(0)[0], 0xFF);  // a new flash is erased

  const uint8_t a[8] = {0xF0, 0x0F, 0xAA, 0x55, 0x00, 0xFF, 0x12, 0x34};
  clock.Set(100);
  ASSERT_TRUE(flash.Program(1024, a, 8).ok());
  EXPECT_EQ(flash.Map(1024)[0], 0xF0);
  EXPECT_EQ(flash.Map(1024)[7], 0x34);
  // Clearing more bits is allowed; setting one (0x0F -> 0x1F) is refused.
  const uint8_t fewer[8] = {0xF0, 0x0F, 0x00, 0x00, 0x00, 0xFF, 0x10, 0x30};
  EXPECT_TRUE(flash.Program(1024, fewer, 8).ok());
  uint8_t more[8];
  for (int i = 0; i < 8; ++i) more[i] = fewer[i];
  more[1] = 0x1F;
  EXPECT_EQ(flash.Program(1024, more, 8).error(), Error::kIoError);
  // Alignment and range are the interface's checks.
  EXPECT_EQ(flash.Program(1020, a, 8).error(), Error::kOutOfRange);
  EXPECT_EQ(flash.Program(4096, a, 8).error(), Error::kOutOfRange);
  EXPECT_EQ(flash.Erase(100).error(), Error::kOutOfRange);

  clock.Set(200);
  ASSERT_TRUE(flash.Erase(1024).ok());
  for (uint32_t i = 1024; i < 2048; ++i) ASSERT_EQ(flash.Map(i)[0], 0xFF) << i;
  EXPECT_EQ(flash.erase_count(), 1u);
  EXPECT_EQ(flash.program_count(), 2u);
  const std::vector<Event> want = {{100, EventKind::kFlashProgram, 0, 1024},
                                   {100, EventKind::kFlashProgram, 0, 1024},
                                   {200, EventKind::kFlashErase, 0, 1024}};
  EXPECT_EQ(timeline.events(), want);
}

TEST(MockFlash, PowerLossTearsOneOperationAndStopsTheRest) {
  MockClock clock;
  MockFlash flash(4096, 1024, 8, &clock, nullptr);
  uint8_t data[32];
  for (int i = 0; i < 32; ++i) data[i] = static_cast<uint8_t>(i);
  flash.InjectPowerLossAfter(1);
  ASSERT_TRUE(flash.Program(0, data, 8).ok());  // the one operation still powered
  // The next program is torn: its first half (16 of 32 bytes, whole units) lands, then it fails.
  EXPECT_EQ(flash.Program(64, data, 32).error(), Error::kIoError);
  EXPECT_FALSE(flash.powered());
  EXPECT_EQ(flash.Map(64)[15], 15);
  EXPECT_EQ(flash.Map(64)[16], 0xFF);
  EXPECT_EQ(flash.Erase(0).error(), Error::kIoError);  // nothing works until power returns
  EXPECT_EQ(flash.Map(0)[3], 3);                       // and nothing was erased
  flash.PowerCycle();
  EXPECT_TRUE(flash.Erase(0).ok());
  EXPECT_EQ(flash.Map(64)[0], 0xFF);

  // A torn erase leaves the first half of the sector erased.
  ASSERT_TRUE(flash.Program(1024, data, 32).ok());
  ASSERT_TRUE(flash.Program(1536, data, 32).ok());
  flash.InjectPowerLossAfter(0);
  EXPECT_EQ(flash.Erase(1024).error(), Error::kIoError);
  EXPECT_EQ(flash.Map(1024)[5], 0xFF);
  EXPECT_EQ(flash.Map(1536)[5], 5);
}

TEST(MockCan, RecordsSentFramesAndHandsOutInjectedOnes) {
  MockClock clock;
  Timeline timeline;
  MockCan can(&clock, &timeline, 2);
  CanFrame f;
  f.id = 0x590;
  f.dlc = 1;
  clock.Set(7);
  EXPECT_TRUE(can.Send(f).ok());
  f.id = 0x710;
  EXPECT_TRUE(can.Send(f).ok());
  EXPECT_EQ(can.Send(f).error(), Error::kFull);  // capacity 2
  const std::vector<CanFrame> sent = can.TakeSent();
  ASSERT_EQ(sent.size(), 2u);
  EXPECT_EQ(sent[0].id, 0x590u);
  EXPECT_EQ(sent[1].id, 0x710u);
  EXPECT_EQ(can.pending_tx(), 0u);
  EXPECT_EQ(timeline.Filter(EventKind::kCanTx).size(), 2u);
  EXPECT_EQ(timeline.events()[0], (Event{7, EventKind::kCanTx, 0, 0x590}));

  CanFrame in;
  EXPECT_FALSE(can.Receive(&in));
  f.id = 0x610;
  can.Inject(f);
  ASSERT_TRUE(can.Receive(&in));
  EXPECT_EQ(in.id, 0x610u);

  EXPECT_TRUE(can.SetBitrate(500000).ok());
  EXPECT_EQ(can.bitrate_bps(), 500000u);
  can.RefuseBitrate(Error::kConfigInvalid);
  EXPECT_EQ(can.SetBitrate(250000).error(), Error::kConfigInvalid);
  EXPECT_EQ(can.bitrate_bps(), 500000u);
  EXPECT_EQ(can.bitrate_changes(), 1u);
}

TEST(MockTickTimer, RateOnlyWhileStoppedAndRefusalsOnRequest) {
  MockTickTimer timer;
  EXPECT_EQ(timer.Start().error(), Error::kNotReady);  // no rate yet
  ASSERT_TRUE(timer.SetRate(50000).ok());
  ASSERT_TRUE(timer.Start().ok());
  EXPECT_TRUE(timer.running());
  EXPECT_EQ(timer.SetRate(1000).error(), Error::kBusy);
  timer.Stop();
  EXPECT_EQ(timer.stops(), 1u);
  timer.RefuseAbove(20000);
  EXPECT_EQ(timer.SetRate(50000).error(), Error::kConfigInvalid);
  EXPECT_TRUE(timer.SetRate(20000).ok());
  EXPECT_EQ(timer.rate_hz(), 20000u);
  EXPECT_TRUE(timer.Start().ok());
  EXPECT_EQ(timer.starts(), 2u);
}

}  // namespace
}  // namespace volcomp::hal::mock
