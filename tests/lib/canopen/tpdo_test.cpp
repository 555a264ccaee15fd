// Transmit PDO: frame-level timing on the node's millisecond clock (change with inhibit time,
// event timer), NMT state and valid bit, mapping changes and mapping checks (CiA
// 301 7.2.2, 7.5.2.35 and 7.5.2.36).
#include "volcomp/canopen/tpdo.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "frames.hpp"
#include "test_values.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using canopen::PdoMapping;
using canopen::SdoAbort;

// Device state (U16), correction-limited flags of axis 1 (U8), applied correction of axis 1
// (I32): 7 bytes.
canopen::TpdoParameters StateMapping() {
  canopen::TpdoParameters p;
  p.cob_id = 0x190;
  p.inhibit_100us = 100;  // 10 ms: 11 ms on the millisecond clock
  p.event_timer_ms = 100;
  p.mapped = 3;
  p.mapping[0] = PdoMapping(0x2122, 0, 16);
  p.mapping[1] = PdoMapping(0x2134, 1, 8);
  p.mapping[2] = PdoMapping(0x2131, 1, 32);
  return p;
}

class TpdoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    values_.values[ObjectId::kDeviceState] = {0x03, 0x00};
    values_.values[ObjectId::kCorrectionLimited1] = {0x00};
    values_.values[ObjectId::kAppliedCorrection1] = {0x00, 0x01, 0x00, 0x00};
    tpdo_.Configure(StateMapping());
  }
  // The frames sent while polling every millisecond up to `until_ms`, as "ms:frame".
  std::vector<std::string> Run(uint32_t until_ms, bool operational = true) {
    std::vector<std::string> out;
    for (; now_ <= until_ms; ++now_) {
      CanFrame f;
      if (tpdo_.Poll(values_, operational, now_, &f)) {
        out.push_back(std::to_string(now_) + ":" + testing::ToString(f));
      }
    }
    return out;
  }
  testing::TestValues values_;
  canopen::Tpdo tpdo_;
  uint32_t now_ = 1000;
};

using Frames = std::vector<std::string>;

TEST_F(TpdoTest, SentOnlyInOperationalAndOnlyWhileValid) {
  EXPECT_EQ(Run(1050, false), Frames{});  // pre-operational or stopped: nothing
  // Operational: the state at once, then by the event timer while nothing changes.
  EXPECT_EQ(Run(1260), (Frames{"1051:190#03000000010000", "1151:190#03000000010000",
                               "1251:190#03000000010000"}));
  // Valid bit set (CiA 301: bit 31 = the PDO does not exist): nothing.
  canopen::TpdoParameters p = StateMapping();
  p.cob_id |= canopen::kPdoCobIdInvalid;
  tpdo_.Configure(p);
  EXPECT_EQ(Run(1500), Frames{});
  // Valid again: sent at once.
  tpdo_.Configure(StateMapping());
  EXPECT_EQ(Run(1501), Frames{"1501:190#03000000010000"});
}

TEST_F(TpdoTest, AChangeIsSentAfterTheInhibitTimeAndTheEventTimerRepeatsIt) {
  EXPECT_EQ(Run(1000), Frames{"1000:190#03000000010000"});
  // A change 2 ms later waits for the inhibit time (11 ms on the ms clock); the value sent is the
  // one current then (the intermediate value is never sent).
  now_ = 1002;
  values_.values[ObjectId::kDeviceState] = {0x07, 0x00};  // fault
  EXPECT_EQ(Run(1005), Frames{});
  values_.values[ObjectId::kCorrectionLimited1] = {0x01};  // clamped
  EXPECT_EQ(Run(1011), Frames{"1011:190#07000100010000"});
  // Changes every millisecond: at most one frame per 11 ms.
  Frames burst;
  for (int i = 0; i < 40; ++i) {
    values_.values[ObjectId::kAppliedCorrection1] = {static_cast<uint8_t>(i), 0x02, 0x00, 0x00};
    const Frames f = Run(now_);
    burst.insert(burst.end(), f.begin(), f.end());
  }
  EXPECT_EQ(burst, (Frames{"1022:190#0700010A020000", "1033:190#07000115020000",
                           "1044:190#07000120020000"}));
  // The last value (39 = 0x27, changed after the last frame) leaves when the inhibit time ends;
  // then quiet: the event timer repeats it 100 ms later.
  EXPECT_EQ(Run(1200), (Frames{"1055:190#07000127020000", "1155:190#07000127020000"}));
}

TEST_F(TpdoTest, NoEventTimerNoInhibitTime) {
  canopen::TpdoParameters p = StateMapping();
  p.inhibit_100us = 0;
  p.event_timer_ms = 0;
  tpdo_.Configure(p);
  EXPECT_EQ(Run(1500), Frames{"1000:190#03000000010000"});  // once, then only on a change
  values_.values[ObjectId::kDeviceState] = {0x01, 0x00};
  EXPECT_EQ(Run(1501), Frames{"1501:190#01000000010000"});
  values_.values[ObjectId::kDeviceState] = {0x03, 0x00};
  EXPECT_EQ(Run(1502), Frames{"1502:190#03000000010000"});
}

TEST_F(TpdoTest, ANewMappingChangesTheFrameLayout) {
  EXPECT_EQ(Run(1000), Frames{"1000:190#03000000010000"});
  canopen::TpdoParameters p = StateMapping();
  p.mapped = 1;
  p.mapping[0] = PdoMapping(0x2122, 0, 16);
  tpdo_.Configure(p);
  EXPECT_EQ(Run(1001), Frames{"1001:190#0300"});
  p.mapped = 0;  // mapping disabled: nothing
  tpdo_.Configure(p);
  EXPECT_EQ(Run(1300), Frames{});
}

TEST(TpdoMapping, OnlyReadableNumericEntriesOfTheirOwnSizeWithinEightBytes) {
  EXPECT_EQ(canopen::CheckTpdoMapping(StateMapping()), SdoAbort::kNone);
  canopen::TpdoParameters p = StateMapping();
  p.mapping[0] = PdoMapping(0x2122, 0, 8);  // wrong length
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kCannotMap);
  p.mapping[0] = PdoMapping(0x2100, 0, 32);  // a DOMAIN
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kCannotMap);
  p.mapping[0] = PdoMapping(0x2110, 0, 32);  // write-only (unlock)
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kCannotMap);
  p.mapping[0] = PdoMapping(0x3000, 0, 32);  // no such object
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kCannotMap);
  p = StateMapping();
  p.mapped = 4;
  p.mapping[3] = PdoMapping(0x2131, 2, 32);  // 88 bits
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kPdoLength);
  p.mapped = 9;
  EXPECT_EQ(canopen::CheckTpdoMapping(p), SdoAbort::kPdoLength);
}

}  // namespace
}  // namespace volcomp
