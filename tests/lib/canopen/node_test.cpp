// NMT slave, heartbeat, EMCY, error register and history, and the object dictionary table.
#include "volcomp/canopen/node.hpp"

#include <gtest/gtest.h>

#include <cstdio>
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
  // Operational: the heartbeat, then the default TPDOs' first frames (0x180 / 0x280 + node-ID,
  // the test values all 0).
  EXPECT_EQ(Drain(n), (Frames{"722#05", "1A2#0000000000000000", "2A2#0000000000000000"}));
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

// The node passes the application's pacing of a domain download on to its SDO server (CiA 301
// block download): the sub-block size follows the application's window (300 bytes: 42 segments of
// 7), and a sub-block's acknowledgement waits until the application's flush reports done (here
// after 3 steps, one per Poll()). Without it the table store programs flash in the receive path.
TEST(Node, DomainBlockDownloadFollowsTheApplicationsPacing) {
  testing::TestValues v;
  v.window = 300;
  v.flush_steps = 3;
  canopen::Node n;
  n.Start(0x05, &v, 0, canopen::CommunicationParameters{0, 0});
  Drain(n);
  // Initiate: ccs 6, CRC, size indicated (400 bytes), 0x2100:0.
  n.OnFrame(F(0x605, "C600210090010000"), 1);
  // scs 5 with CRC support, 0x2100:0, blksize 42.
  EXPECT_EQ(Drain(n), Frames{"585#A40021002A000000"});
  for (int seq = 1; seq <= 42; ++seq) {
    char data[17];
    std::snprintf(data, sizeof data, "%02X%014X", seq, 0);
    n.OnFrame(F(0x605, data), 2);
  }
  n.Poll(2);
  n.Poll(2);
  EXPECT_EQ(Drain(n), Frames{});  // two flush steps: still holding the acknowledgement
  EXPECT_EQ(v.flushes, 2);
  n.Poll(3);
  EXPECT_EQ(v.flushes, 3);
  EXPECT_EQ(Drain(n), Frames{"585#A22A2A0000000000"});  // 42 segments taken, next blksize 42
  EXPECT_EQ(v.domain.size(), 41u * 7u);  // the last segment of a sub-block is held back
}

TEST(Node, EmcyErrorRegisterAndHistory) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x05, &v, 0, canopen::CommunicationParameters{0, 0});  // no heartbeat, no inhibit
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

// 0x1015 = 100 (10 ms): the second EMCY waits until the node's clock shows 11 ms since the first
// (10 ms rounded up, plus one for the clock's 1 ms resolution); the first after a quiet spell
// leaves at once.
TEST(Node, EmcyInhibitTimeSpacesEmcys) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x05, &v, 1000, canopen::CommunicationParameters{0, 100});
  EXPECT_EQ(Drain(n), Frames{"705#00"});
  n.OnFrame(F(0x605, "4015100000000000"), 1000);  // 0x1015 reads 100
  EXPECT_EQ(Drain(n), Frames{"585#4B15100064000000"});
  n.ReportEvent(0xFF10, 0, 0x08000020);  // an EMCY and its "errors cleared"
  EXPECT_EQ(Drain(n), Frames{"085#10FF012000000800"});
  n.Poll(1010);
  EXPECT_EQ(Drain(n), Frames{});
  n.Poll(1011);
  EXPECT_EQ(Drain(n), Frames{"085#0000000000000000"});
  n.Poll(1100);
  EXPECT_EQ(Drain(n), Frames{});
  n.RaiseError(0xFF01, canopen::kErrManufacturer);  // quiet for 89 ms: at once
  EXPECT_EQ(Drain(n), Frames{"085#01FF810000000000"});
  // Written to 0 over SDO: no inhibit.
  n.OnFrame(F(0x605, "2B15100000000000"), 1100);
  EXPECT_EQ(Drain(n), Frames{"585#6015100000000000"});
  n.ClearErrors();
  n.RaiseError(0xFF02, canopen::kErrManufacturer);
  EXPECT_EQ(Drain(n), (Frames{"085#0000000000000000", "085#02FF810000000000"}));
  EXPECT_EQ(n.emcy_sent(), 5u);
  EXPECT_EQ(n.emcy_suppressed(), 0u);
}

// More EMCYs than the queue holds within the inhibit time: the newest waiting one gives way, so
// the last EMCY sent carries the last error raised; each replaced one is counted, none is lost
// from the history.
TEST(Node, EmcyQueueKeepsTheLatestWhenFull) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x05, &v, 0, canopen::CommunicationParameters{0, 10});  // 1 ms: 2 ms on the clock
  Drain(n);
  for (uint16_t code = 0xFF20; code < 0xFF20 + 11; ++code) n.RaiseError(code, 0);
  // 8 wait; each of the last 3 replaced the newest waiting one.
  EXPECT_EQ(n.emcy_suppressed(), 3u);
  Frames out;
  for (uint32_t t = 0; t <= 40; ++t) {
    n.Poll(t);
    for (const std::string& f : Drain(n)) out.push_back(f);
  }
  EXPECT_EQ(out, (Frames{"085#20FF010000000000", "085#21FF010000000000", "085#22FF010000000000",
                         "085#23FF010000000000", "085#24FF010000000000", "085#25FF010000000000",
                         "085#26FF010000000000", "085#2AFF010000000000"}));
  n.OnFrame(F(0x605, "4003100000000000"), 41);  // 0x1003:0 = 8 recorded (its maximum)
  n.OnFrame(F(0x605, "4003100100000000"), 41);  // newest: 0xFF2A
  n.Poll(41);
  EXPECT_EQ(Drain(n), (Frames{"585#4F03100008000000", "585#430310012AFF0000"}));
}

// An EMCY raised before the node starts (a stored table found invalid at power-up) goes out after
// the boot-up message.
TEST(Node, EmcyBeforeStartFollowsTheBootUp) {
  testing::TestValues v;
  canopen::Node n;
  const uint8_t m[5] = {7, 0, 0, 0, 0};
  n.RaiseError(0x6300, canopen::kErrManufacturer, m);
  n.Start(0x05, &v, 0);
  EXPECT_EQ(Drain(n), (Frames{"705#00", "085#0063810700000000"}));
}

// NMT reset communication restores the communication parameters to their stored values (CiA 301
// 7.3.2.2.2): written 0x1017 and 0x1015 do not survive it.
TEST(Node, ResetCommunicationRestoresTheStoredParameters) {
  testing::TestValues v;
  canopen::Node n;
  n.Start(0x05, &v, 0, canopen::CommunicationParameters{1000, 100});
  Drain(n);
  n.OnFrame(F(0x605, "2B17100064000000"), 1);  // 0x1017 = 100 ms
  n.OnFrame(F(0x605, "2B15100000000000"), 1);  // 0x1015 = 0
  EXPECT_EQ(Drain(n), (Frames{"585#6017100000000000", "585#6015100000000000"}));
  n.Poll(101);
  EXPECT_EQ(Drain(n), Frames{"705#7F"});  // heartbeat every 100 ms now
  n.OnFrame(F(0x000, "8205"), 150);
  EXPECT_EQ(n.TakeResetRequest(), canopen::ResetRequest::kCommunication);
  n.ResetCommunication(150);
  EXPECT_EQ(Drain(n), Frames{"705#00"});
  n.OnFrame(F(0x605, "4017100000000000"), 151);
  n.OnFrame(F(0x605, "4015100000000000"), 151);
  EXPECT_EQ(Drain(n), (Frames{"585#4B171000E8030000", "585#4B15100064000000"}));
  n.Poll(1149);
  EXPECT_EQ(Drain(n), Frames{});
  n.Poll(1150);
  EXPECT_EQ(Drain(n), Frames{"705#7F"});
  // Stored since (the application's 0x1010): a reset keeps the new value.
  n.OnFrame(F(0x605, "2B171000F4010000"), 1200);  // 500 ms
  Drain(n);
  n.set_stored_communication(n.communication());
  n.ResetCommunication(1300);
  Drain(n);
  n.OnFrame(F(0x605, "4017100000000000"), 1301);
  EXPECT_EQ(Drain(n), Frames{"585#4B171000F4010000"});
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
  // whose sub 0 is the number of errors recorded, and the PDO mappings 0x1A00.., whose sub 0 is
  // the number of entries mapped: their 8 entries exist).
  for (size_t h = 0; h < canopen::kObjectHeaderCount; ++h) {
    const auto& o = canopen::kObjectHeaders[h];
    if (o.index == 0x1003) continue;
    if (o.index >= 0x1A00 && o.index <= 0x1BFF) {
      EXPECT_NE(canopen::FindEntry(o.index, 8), nullptr) << std::hex << o.index;
      EXPECT_EQ(canopen::FindEntry(o.index, 9), nullptr) << std::hex << o.index;
      continue;
    }
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
