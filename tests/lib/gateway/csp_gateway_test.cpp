// The CSP gateway logic (lib/csp_gateway): which frames are forwarded untouched, how target and
// actual positions are corrected (offsets, wrap-around, inverted axes, the SYNC association of
// feedback), frames for the board itself, and configuration checks; the control tick's two ends
// on the gateway (CspInput, CspOutput). Expected frames are written out byte by byte here.
#include "volcomp/gateway/csp_gateway.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "csp_drives.hpp"
#include "frames.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/gateway/csp_stages.hpp"

namespace volcomp {
namespace {

using gateway::CspGateway;
using gateway::FeedbackMode;
using gateway::GatewayConfig;
using gateway::PdoField;
using gateway::Route;
using testing::F;
using testing::ToString;

constexpr uint8_t kBoardNode = 0x10;

GatewayConfig ThreeDrives() { return testing::CspDriveMapping(3, kBoardNode); }

CanFrame Pdo(uint32_t id, uint16_t word, int32_t pos) { return testing::CspPdo(id, pos, word); }
using testing::CspPdoPosition;

class GatewayTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(gw_.Configure(ThreeDrives(), 3).ok()); }
  CanFrame Down(const CanFrame& in, Route want = Route::kForward) {
    CanFrame out;
    EXPECT_EQ(gw_.FromController(in, &out), want) << ToString(in);
    return out;
  }
  CanFrame Up(const CanFrame& in, Route want = Route::kForward) {
    CanFrame out;
    EXPECT_EQ(gw_.FromDrive(in, &out), want) << ToString(in);
    return out;
  }
  CspGateway gw_;
};

TEST_F(GatewayTest, ForwardsEverythingElseBitForBit) {
  for (int a = 0; a < 3; ++a) gw_.SetCorrection(static_cast<uint8_t>(a), 1234);
  const std::vector<CanFrame> down = {
      F(0x080, ""),                  // SYNC
      F(0x000, "0100"),              // NMT start all
      F(0x000, "8201"),              // NMT reset communication of node 1
      F(0x601, "4041600000000000"),  // SDO upload request to drive 1
      F(0x602, "2B40600006000000"),  // SDO download to drive 2
      F(0x301, "0F00E8030000"),      // RPDO2 of drive 1 (not mapped)
      F(0x7E5, "0400000000000000"),  // LSS
      F(0x100, "0102030405060708"),  // time stamp
  };
  for (const CanFrame& f : down) EXPECT_EQ(Down(f), f) << ToString(f);
  const std::vector<CanFrame> up = {
      F(0x581, "4B41600037120000"),  // SDO response of drive 1
      F(0x082, "1032010000000000"),  // EMCY of drive 2
      F(0x703, "05"),                // heartbeat of drive 3
      F(0x281, "3712E8030000"),      // TPDO2 of drive 1 (not mapped)
      F(0x201, "0F00E8030000"),      // a target COB-ID arriving from the drive side
  };
  for (const CanFrame& f : up) EXPECT_EQ(Up(f), f) << ToString(f);
  // An actual-position COB-ID coming from the controller side is not touched either.
  const CanFrame tpdo_down = Pdo(0x181, 0x1237, 500);
  EXPECT_EQ(Down(tpdo_down), tpdo_down);
  // Remote frames and extended frames with a mapped identifier are not PDOs.
  CanFrame rtr;
  rtr.id = 0x201;
  rtr.rtr = true;
  rtr.dlc = 6;
  EXPECT_EQ(Down(rtr), rtr);
  CanFrame ext = Pdo(0x201, 0x000F, 1000);
  ext.extended = true;
  EXPECT_EQ(Down(ext), ext);
  EXPECT_EQ(gw_.counters().targets_corrected, 0u);
  EXPECT_EQ(gw_.counters().actuals_corrected, 0u);
  EXPECT_EQ(gw_.counters().syncs, 1u);
}

TEST_F(GatewayTest, AddsTheCorrectionToTheTargetAndLeavesTheRestOfThePdo) {
  gw_.SetCorrection(0, 37);
  gw_.SetCorrection(1, -12);
  EXPECT_EQ(ToString(Down(F(0x201, "0F00E8030000"))), "201#0F000D040000");  // 1000 + 37 = 1037
  EXPECT_EQ(ToString(Down(F(0x202, "1F00E8030000AABB"))), "202#1F00DC030000AABB");  // 988
  EXPECT_EQ(ToString(Down(F(0x203, "0F00E8030000"))), "203#0F00E8030000");          // no correction
  EXPECT_EQ(gw_.counters().targets_corrected, 3u);
  EXPECT_EQ(gw_.last_target(0), 1000);
  EXPECT_EQ(gw_.sent_correction(0), 37);
  EXPECT_EQ(gw_.sent_correction(1), -12);
}

TEST_F(GatewayTest, PositionsWrapLikeInteger32) {
  gw_.SetCorrection(0, 5);
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x201, 0x0F, INT32_MAX))), INT32_MIN + 4);
  gw_.SetCorrection(0, -5);
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x201, 0x0F, INT32_MIN + 2))), INT32_MAX - 2);
  // The commanded position keeps counting across the wrap (relative to the first target).
  EXPECT_EQ(gw_.InputCounter(0), 3u);
}

TEST_F(GatewayTest, InputCounterIsRelativeToTheFirstTarget) {
  EXPECT_EQ(gw_.InputCounter(0), 0u);
  EXPECT_FALSE(gw_.has_target(0));
  Down(Pdo(0x201, 0x0F, 500000));
  EXPECT_TRUE(gw_.has_target(0));
  EXPECT_EQ(gw_.InputCounter(0), 0u);
  Down(Pdo(0x201, 0x0F, 500250));
  EXPECT_EQ(gw_.InputCounter(0), 250u);
  Down(Pdo(0x201, 0x0F, 499000));
  EXPECT_EQ(static_cast<int32_t>(gw_.InputCounter(0)), -1000);
  EXPECT_EQ(gw_.InputCounter(1), 0u);  // never commanded
}

TEST_F(GatewayTest, FeedbackLosesTheCorrectionOfTheTargetTakenOverAtSync) {
  // Order 1: SYNC, then the RPDOs of the next cycle (drive takes them over at the next SYNC).
  gw_.SetCorrection(0, 10);
  Down(F(0x080, ""));
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x201, 0x0F, 1000))), 1010);  // cycle 1 target
  gw_.SetCorrection(0, 20);
  Down(F(0x080, ""));  // the drive takes over 1010
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x201, 0x0F, 1100))),
            1120);  // cycle 2 target, sent before the TPDO
  // The drive reports 1010 (it follows perfectly): the controller must see its 1000.
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x181, 0x1237, 1010))), 1000);
  EXPECT_EQ(gw_.feedback_correction(0), 10);
  Down(F(0x080, ""));  // the drive takes over 1120
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x181, 0x1237, 1120))), 1100);
  // A following error of the drive itself stays visible to the controller.
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x181, 0x1237, 1117))), 1097);
}

TEST_F(GatewayTest, FeedbackWithTargetsSentBeforeSync) {
  // Order 2: the RPDO of a cycle precedes its SYNC; the drive applies it at that SYNC.
  gw_.SetCorrection(1, -7);
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x202, 0x0F, 2000))), 1993);
  Down(F(0x080, ""));
  gw_.SetCorrection(1, -9);
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x202, 0x0F, 2050))), 2041);  // next cycle, before the TPDO
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x182, 0x1237, 1993))), 2000);
}

TEST_F(GatewayTest, LatestFeedbackModeUsesTheLastForwardedTarget) {
  GatewayConfig c = ThreeDrives();
  c.feedback = FeedbackMode::kLatest;
  ASSERT_TRUE(gw_.Configure(c, 3).ok());
  gw_.SetCorrection(2, 4);
  Down(Pdo(0x203, 0x0F, 100));
  gw_.SetCorrection(2, 6);
  Down(Pdo(0x203, 0x0F, 200));
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x183, 0x1237, 206))), 200);  // no SYNC at all
}

TEST_F(GatewayTest, InvertedAxisCountsAgainstTheDrive) {
  GatewayConfig c = ThreeDrives();
  c.invert[0] = true;
  ASSERT_TRUE(gw_.Configure(c, 3).ok());
  gw_.SetCorrection(0, 10);  // +10 machine steps = -10 drive increments
  EXPECT_EQ(CspPdoPosition(Down(Pdo(0x201, 0x0F, 5000))), 4990);
  Down(F(0x080, ""));
  EXPECT_EQ(CspPdoPosition(Up(Pdo(0x181, 0x1237, 4990))), 5000);
  Down(Pdo(0x201, 0x0F, 4900));  // the drive moves -100: the machine axis +100
  EXPECT_EQ(gw_.InputCounter(0), 100u);
}

TEST_F(GatewayTest, TwoAxesInOnePdo) {
  GatewayConfig c;
  c.own_node_id = kBoardNode;
  c.map[c.map_count++] = {0x301, PdoField::kTargetPosition, 0, 0};
  c.map[c.map_count++] = {0x301, PdoField::kTargetPosition, 4, 1};
  c.map[c.map_count++] = {0x281, PdoField::kActualPosition, 0, 0};
  c.map[c.map_count++] = {0x281, PdoField::kActualPosition, 4, 1};
  ASSERT_TRUE(gw_.Configure(c, 2).ok());
  gw_.SetCorrection(0, 1);
  gw_.SetCorrection(1, -1);
  EXPECT_EQ(ToString(Down(F(0x301, "0A000000F4010000"))), "301#0B000000F3010000");
  Down(F(0x080, ""));
  EXPECT_EQ(ToString(Up(F(0x281, "0B000000F3010000"))), "281#0A000000F4010000");
}

TEST_F(GatewayTest, ShortPdoIsForwardedUntouchedAndCounted) {
  gw_.SetCorrection(0, 9);
  const CanFrame shorty = F(0x201, "0F00E80300");  // 5 bytes: the position needs 2..5
  EXPECT_EQ(Down(shorty), shorty);
  EXPECT_EQ(gw_.counters().short_pdos, 1u);
  EXPECT_FALSE(gw_.has_target(0));
}

TEST_F(GatewayTest, FramesOfTheBoardItself) {
  // The board's own SDO server: handled locally, not forwarded.
  Down(F(0x610, "4000100000000000"), Route::kLocal);
  EXPECT_EQ(gw_.counters().local, 1u);
  // Another node's SDO goes through.
  Down(F(0x611, "4000100000000000"));
  // From the drive side, the board's own COB-IDs would collide on the controller bus.
  Up(F(0x590, "4300100000000000"), Route::kDrop);
  Up(F(0x710, "05"), Route::kDrop);
  Up(F(0x090, "0000000000000000"), Route::kDrop);
  EXPECT_EQ(gw_.counters().conflicts, 3u);
  // Without a node on the bus nothing is local.
  GatewayConfig c = ThreeDrives();
  c.own_node_id = 0;
  ASSERT_TRUE(gw_.Configure(c, 3).ok());
  Down(F(0x610, "4000100000000000"), Route::kForward);
  Up(F(0x590, "4300100000000000"), Route::kForward);
}

TEST_F(GatewayTest, CountsFrames) {
  Down(F(0x080, ""));
  Down(Pdo(0x201, 0x0F, 1));
  Up(Pdo(0x181, 0x1237, 1));
  Up(F(0x701, "05"));
  EXPECT_EQ(gw_.counters().from_controller, 2u);
  EXPECT_EQ(gw_.counters().from_drives, 2u);
  EXPECT_EQ(gw_.counters().targets_corrected, 1u);
  EXPECT_EQ(gw_.counters().actuals_corrected, 1u);
}

TEST(GatewayConfigTest, RejectsInconsistentMappings) {
  const GatewayConfig good = ThreeDrives();
  EXPECT_TRUE(gateway::ValidateGatewayConfig(good, 3).ok());
  EXPECT_FALSE(gateway::ValidateGatewayConfig(good, 2).ok());  // axis 2 does not exist
  EXPECT_FALSE(gateway::ValidateGatewayConfig(good, 0).ok());

  auto broken = [&](auto edit) {
    GatewayConfig c = good;
    edit(c);
    return gateway::ValidateGatewayConfig(c, 3).ok();
  };
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].cob_id = 0x000; }));  // NMT
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].cob_id = 0x800; }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].cob_id = 0x080; }));  // SYNC
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].cob_id = 0x610; }));  // the board's SDO
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[1].cob_id = 0x710; }));  // its heartbeat
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].offset = 5; }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[2].axis = 0; }));  // two targets for axis 0
  EXPECT_FALSE(broken([](GatewayConfig& c) {  // overlapping fields in one PDO
    c.map[2].cob_id = 0x201;
    c.map[2].offset = 4;
  }));
  EXPECT_TRUE(broken([](GatewayConfig& c) {  // adjacent fields are fine
    c.map[2].cob_id = 0x201;
    c.map[0].offset = 0;
    c.map[2].offset = 4;
  }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map_count = gateway::kMaxPdoMaps + 1; }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.own_node_id = 128; }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.sync_cob_id = 0; }));
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.sync_cob_id = 0x610; }));  // the board's SDO
  EXPECT_FALSE(broken([](GatewayConfig& c) { c.map[0].field = static_cast<PdoField>(7); }));
  // A rejected configuration leaves the gateway as it was.
  CspGateway gw;
  ASSERT_TRUE(gw.Configure(good, 3).ok());
  GatewayConfig bad = good;
  bad.map[0].offset = 6;
  EXPECT_FALSE(gw.Configure(bad, 3).ok());
  EXPECT_EQ(gw.config().map[0].offset, 2);
}

// The tick's ends on the gateway: the input stage reads the commanded positions of the target
// PDOs (machine direction, from the first target), the output stage puts the tick's corrections
// into the targets forwarded next (drive direction for an inverted axis).
TEST(CspStages, InputReadsCommandedPositionsOutputCorrectsTheNextTargets) {
  GatewayConfig c = ThreeDrives();
  c.invert[1] = true;
  CspGateway gw;
  ASSERT_TRUE(gw.Configure(c, 3).ok());
  gateway::CspInput input(&gw);
  gateway::CspOutput output(&gw);
  BoardConfig board = DefaultBoardConfig();
  ASSERT_TRUE(output.Configure(board).ok());
  uint32_t counters[table::kMaxAxes];
  input.ReadCounters(counters);
  for (uint32_t v : counters) EXPECT_EQ(v, 0u);  // no target yet
  CanFrame out;
  gw.FromController(Pdo(0x201, 0x0F, 1000), &out);
  gw.FromController(Pdo(0x202, 0x0F, 500), &out);
  gw.FromController(Pdo(0x201, 0x0F, 1025), &out);
  gw.FromController(Pdo(0x202, 0x0F, 480), &out);  // inverted axis: -20 drive = +20 machine
  input.ReadCounters(counters);
  EXPECT_EQ(counters[0], 25u);
  EXPECT_EQ(counters[1], 20u);
  EXPECT_EQ(counters[2], 0u);
  // A tick: targets = commanded + corrections (machine steps).
  const int32_t corrections[3] = {7, -3, 0};
  const int32_t targets[3] = {25 + 7, 20 - 3, 0};
  output.Apply(targets, corrections);
  EXPECT_EQ(output.position(0), 32);
  EXPECT_EQ(output.position(1), 17);
  gw.FromController(Pdo(0x201, 0x0F, 1030), &out);
  EXPECT_EQ(CspPdoPosition(out), 1037);
  gw.FromController(Pdo(0x202, 0x0F, 470), &out);
  EXPECT_EQ(CspPdoPosition(out), 473);  // -3 machine steps = +3 drive increments
  // More axes than a board may have are refused.
  board.axis_count = table::kMaxAxes + 1;
  EXPECT_EQ(output.Configure(board).error(), Error::kConfigInvalid);
}

}  // namespace
}  // namespace volcomp
