// BoardPolicy, the board owner's rules for the bus: write access (input or a timed unlock), table
// activation (referenced and still; the one activation sequence against the settings in force),
// reference requests (not during a fault). On a real ControlTick and TableHandOver.
#include "volcomp/firmware/board_policy.hpp"

#include <gtest/gtest.h>

#include <atomic>

#include "test_tables.hpp"
#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp::firmware {
namespace {

using canopen::SdoAbort;

testing::AlignedBytes SmallImage(uint32_t id) {
  testing::GridCase g;
  for (auto& d : g.dim) d = {2, -1000, 1000};
  g.i16.assign(g.count(), 3);
  g.steps.assign(g.count(), 3);
  return testing::WriteGridImage(g, id);
}

class BoardPolicyTest : public ::testing::Test {
 protected:
  BoardPolicyTest() : policy_({&settings_, &tick_, &hand_over_, &references_, &thermal_}) {
    settings_.board.tick_hz = 10000;
    EXPECT_TRUE(tick_.Configure(settings_.board).ok());
    thermal_.Start(settings_, &tick_.compensator(), 0);
  }
  // `n` ticks without input steps.
  void Idle(int n) {
    for (int i = 0; i < n; ++i) tick_.Run(counters_);
  }
  void Step(uint8_t axis) {
    ++counters_[axis];
    tick_.Run(counters_);
  }

  BoardSettings settings_;
  ControlTick tick_;
  TableHandOver hand_over_;
  std::atomic<uint8_t> references_{0};
  BoardThermal thermal_;
  BoardPolicy policy_;
  uint32_t counters_[table::kMaxAxes] = {};
};

TEST_F(BoardPolicyTest, WritableWithTheInputOrWithinTheUnlockTime) {
  EXPECT_FALSE(policy_.writable());
  policy_.SetLines(true, false);
  EXPECT_TRUE(policy_.writable());
  policy_.SetLines(false, false);
  policy_.set_now_ms(1000);
  EXPECT_EQ(policy_.WriteUnlock(canopen::kUnlockSignature), SdoAbort::kNone);
  EXPECT_TRUE(policy_.writable());
  policy_.set_now_ms(1000 + kUnlockMs - 1);
  EXPECT_TRUE(policy_.writable());
  policy_.set_now_ms(1000 + kUnlockMs);
  EXPECT_FALSE(policy_.writable());
  // 0 locks quietly, anything else locks and is refused.
  EXPECT_EQ(policy_.WriteUnlock(canopen::kUnlockSignature), SdoAbort::kNone);
  EXPECT_EQ(policy_.WriteUnlock(0), SdoAbort::kNone);
  EXPECT_FALSE(policy_.writable());
  EXPECT_EQ(policy_.WriteUnlock(canopen::kUnlockSignature), SdoAbort::kNone);
  EXPECT_EQ(policy_.WriteUnlock(0x12345678), SdoAbort::kInvalidValue);
  EXPECT_FALSE(policy_.writable());
  // A start locks.
  EXPECT_EQ(policy_.WriteUnlock(canopen::kUnlockSignature), SdoAbort::kNone);
  policy_.Restart();
  EXPECT_FALSE(policy_.writable());
}

TEST_F(BoardPolicyTest, ActivationNeedsEveryAxisReferencedAndStill) {
  Idle(1);
  EXPECT_FALSE(policy_.moving());
  EXPECT_EQ(policy_.MayActivate(), SdoAbort::kDeviceState);  // not referenced
  tick_.ReferenceAxes(0x3);
  EXPECT_EQ(policy_.MayActivate(), SdoAbort::kDeviceState);  // axis 3 not referenced
  tick_.ReferenceAxes(0x4);
  EXPECT_EQ(policy_.MayActivate(), SdoAbort::kNone);
  Step(0);
  EXPECT_TRUE(policy_.moving());
  EXPECT_EQ(policy_.MayActivate(), SdoAbort::kDeviceState);
  // Still for kStillMs at the tick rate of the settings in force.
  const int still_ticks = static_cast<int>(kStillMs * settings_.board.tick_hz / 1000);
  Idle(still_ticks - 1);
  EXPECT_TRUE(policy_.moving());
  Idle(1);
  EXPECT_FALSE(policy_.moving());
  EXPECT_EQ(policy_.MayActivate(), SdoAbort::kNone);
}

TEST_F(BoardPolicyTest, ActivateHandsThePreparedTableToTheTickAndMarksItActive) {
  const testing::AlignedBytes img = SmallImage(0x51);
  const Result<table::TableView> view = table::ParseImage(img.data(), img.size());
  ASSERT_TRUE(view.ok());
  EXPECT_FALSE(policy_.table_active());
  EXPECT_EQ(policy_.active_table_id(), 0u);
  ASSERT_TRUE(policy_.Activate(*view).ok());
  EXPECT_TRUE(policy_.table_active());
  EXPECT_EQ(policy_.active_table_id(), 0x51u);
  EXPECT_EQ(policy_.active_table_crc(), view->crc32);
  const PreparedTable* taken = nullptr;
  ASSERT_TRUE(hand_over_.Take(&taken));
  EXPECT_NE(taken, nullptr);
  policy_.Deactivate();
  EXPECT_FALSE(policy_.table_active());
  EXPECT_EQ(policy_.active_table_crc(), 0u);
  ASSERT_TRUE(hand_over_.Take(&taken));
  EXPECT_EQ(taken, nullptr);
  // A table for other axes than the settings in force: refused, nothing handed over.
  settings_.board.axis[0].resolution_e9 = 500000;
  EXPECT_FALSE(policy_.Activate(*view).ok());
  EXPECT_FALSE(policy_.table_active());
  EXPECT_FALSE(hand_over_.Take(&taken));
}

TEST_F(BoardPolicyTest, ReferenceRequestsWaitOutAFault) {
  policy_.RequestReference(0x1);
  EXPECT_EQ(references_.load(), 0x1);
  policy_.SetLines(false, true);
  policy_.RequestReference(0x6);
  EXPECT_EQ(references_.load(), 0x1);
  policy_.SetLines(false, false);
  policy_.RequestReference(0x4);
  EXPECT_EQ(references_.load(), 0x5);
  EXPECT_TRUE(policy_.bus_enable());
  policy_.SetBusEnable(false);
  EXPECT_FALSE(policy_.bus_enable());
}

}  // namespace
}  // namespace volcomp::firmware
