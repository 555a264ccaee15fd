// NMT slave, heartbeat, EMCY, error register and history, and the object dictionary table.
#include "volcomp/canopen/node.hpp"

#include <gtest/gtest.h>

#include <set>

#include "frames.hpp"
#include "test_values.hpp"
#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp {
namespace {

using testing::F;
using testing::ToString;
using Frames = std::vector<std::string>;

Frames Drain(canopen::Node& n) {
  Frames out;
  CanFrame f;
  while (n.PopTx(&f)) out.push_back(ToString(f));
  return out;
}

TEST(Node, BootUpHeartbeatAndNmtStates) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x22, &v, 0);
  EXPECT_EQ(Drain(n), Frames{"722#00"});
  EXPECT_EQ(n.state(), canopen::NmtState::kPreOperational);
  n.set_heartbeat_ms(100);
  n.Poll(99);
  EXPECT_EQ(Drain(n), Frames{});
  n.Poll(100);
  EXPECT_EQ(Drain(n), Frames{"722#7F"});
  n.OnFrame(F(0x000, "0122"), 150);  // start this node
  EXPECT_EQ(n.state(), canopen::NmtState::kOperational);
  n.Poll(200);
  EXPECT_EQ(Drain(n), Frames{"722#05"});
  n.OnFrame(F(0x000, "0233"), 210);  // another node: ignored
  EXPECT_EQ(n.state(), canopen::NmtState::kOperational);
  n.OnFrame(F(0x000, "0200"), 220);  // broadcast stop
  EXPECT_EQ(n.state(), canopen::NmtState::kStopped);
  // Stopped: SDO is not served.
  n.OnFrame(F(0x622, "4000100000000000"), 230);
  n.Poll(230);
  EXPECT_EQ(Drain(n), Frames{});
  n.Poll(300);
  EXPECT_EQ(Drain(n), Frames{"722#04"});
  n.OnFrame(F(0x000, "8022"), 310);
  EXPECT_EQ(n.state(), canopen::NmtState::kPreOperational);
  n.OnFrame(F(0x000, "8222"), 320);
  EXPECT_EQ(n.TakeResetRequest(), canopen::ResetRequest::kCommunication);
  EXPECT_EQ(n.TakeResetRequest(), canopen::ResetRequest::kNone);
  n.OnFrame(F(0x000, "8100"), 330);
  EXPECT_EQ(n.TakeResetRequest(), canopen::ResetRequest::kNode);
  n.OnFrame(F(0x000, "81"), 340);  // malformed NMT (DLC 1)
  EXPECT_EQ(n.malformed(), 1u);
}

TEST(Node, EmcyErrorRegisterAndHistory) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x05, &v, 0);
  n.set_heartbeat_ms(0);
  Drain(n);
  const uint8_t m[5] = {1, 2, 3, 4, 5};
  n.RaiseError(0xFF01, canopen::kErrManufacturer, m);
  EXPECT_EQ(Drain(n), Frames{"085#01FF810102030405"});
  EXPECT_EQ(n.error_register(), 0x81);
  n.RaiseError(0x8130, canopen::kErrCommunication);
  Drain(n);
  // 0x1001 and 0x1003 through SDO.
  n.OnFrame(F(0x605, "4001100000000000"), 1);
  n.OnFrame(F(0x605, "4003100000000000"), 1);
  n.OnFrame(F(0x605, "4003100100000000"), 1);
  n.OnFrame(F(0x605, "4003100200000000"), 1);
  EXPECT_EQ(Drain(n), (Frames{"585#4F01100091000000", "585#4F03100002000000",
                              "585#4303100130810000", "585#4303100201FF0000"}));
  n.OnFrame(F(0x605, "2F03100000000000"), 2);  // clear the history
  n.OnFrame(F(0x605, "2F03100003000000"), 2);  // only 0 may be written
  EXPECT_EQ(Drain(n), (Frames{"585#6003100000000000", "585#8003100030000906"}));
  n.ClearErrors();
  EXPECT_EQ(Drain(n), Frames{"085#0000000000000000"});
  EXPECT_EQ(n.error_register(), 0);
}

TEST(ObjectDictionary, TableIsSortedUniqueAndConsistent) {
  std::set<uint32_t> keys;
  uint32_t prev = 0;
  for (size_t i = 0; i < canopen::kObjectEntryCount; ++i) {
    const auto& e = canopen::kObjectEntries[i];
    const uint32_t key = (uint32_t{e.index} << 8) | e.sub;
    EXPECT_GT(key, i == 0 ? 0u : prev) << std::hex << key;
    prev = key;
    EXPECT_EQ(canopen::FindEntry(e.index, e.sub), &e);
    EXPECT_EQ(&canopen::Entry(e.id), &e);
  }
  bool exists = true;
  EXPECT_EQ(canopen::FindEntry(0x1018, 9, &exists), nullptr);
  EXPECT_TRUE(exists);
  EXPECT_EQ(canopen::FindEntry(0x3000, 0, &exists), nullptr);
  EXPECT_FALSE(exists);
  // Every array/record header's sub 0 gives the highest sub-index that exists (except 0x1003,
  // whose sub 0 is the number of errors recorded).
  for (size_t h = 0; h < canopen::kObjectHeaderCount; ++h) {
    const auto& o = canopen::kObjectHeaders[h];
    if (o.index == 0x1003) continue;
    if (o.kind == canopen::ObjectKind::kVar) {
      EXPECT_NE(canopen::FindEntry(o.index, 0), nullptr) << std::hex << o.index;
      continue;
    }
    const auto* sub0 = canopen::FindEntry(o.index, 0);
    ASSERT_NE(sub0, nullptr) << std::hex << o.index;
    const auto n = static_cast<uint8_t>(sub0->default_value);
    EXPECT_NE(canopen::FindEntry(o.index, n), nullptr) << std::hex << o.index;
    EXPECT_EQ(canopen::FindEntry(o.index, static_cast<uint8_t>(n + 1)), nullptr)
        << std::hex << o.index;
  }
}

}  // namespace
}  // namespace volcomp
