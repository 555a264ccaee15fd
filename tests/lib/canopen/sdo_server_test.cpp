// SDO server: frame-exact protocol traces and injected faults (CiA 301 7.2.4).
#include <gtest/gtest.h>

#include <random>

#include "frames.hpp"
#include "test_values.hpp"
#include "volcomp/canopen/crc16.hpp"
#include "volcomp/canopen/node.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp {
namespace {

using canopen::ObjectId;
using testing::F;
using testing::ToString;

class SdoServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // No heartbeat and no EMCY inhibit time: the traces show every frame as it is caused (the
    // inhibit time has its own test in node_test.cpp).
    node_.Start(0x10, &values_, now_, canopen::CommunicationParameters{0, 0});
    Drain();  // boot-up
  }
  std::vector<std::string> Drain() {
    std::vector<std::string> out;
    CanFrame f;
    while (node_.PopTx(&f)) out.push_back(ToString(f));
    return out;
  }
  std::vector<std::string> Send(const std::string& hex) {
    node_.OnFrame(F(0x610, hex), now_);
    node_.Poll(now_);
    return Drain();
  }
  void Advance(uint32_t ms) {
    now_ += ms;
    node_.Poll(now_);
  }

  testing::TestValues values_;
  canopen::Node node_;
  uint32_t now_ = 1000;
};

using Frames = std::vector<std::string>;

TEST(Crc16, CheckValuesOfCia301BlockTransfer) {
  const std::string s = "123456789";
  EXPECT_EQ(canopen::Crc16Update(0, reinterpret_cast<const uint8_t*>(s.data()), s.size()), 0x31C3);
  const std::string t = "0123456789ABCDEFGHIJ";
  EXPECT_EQ(canopen::Crc16Update(0, reinterpret_cast<const uint8_t*>(t.data()), t.size()), 0x34F1);
}

TEST_F(SdoServerTest, BlockDownloadTraceMatchesTheSpecificationExample) {
  // "0123456789ABCDEFGHIJ" (20 bytes) into the DOMAIN 0x2100:00, CRC on.
  EXPECT_EQ(Send("C600210014000000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Send("0130313233343536"), Frames{});
  EXPECT_EQ(Send("0237383941424344"), Frames{});
  EXPECT_EQ(Send("8345464748494A00"), Frames{"590#A2037F0000000000"});
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(std::string(values_.domain.begin(), values_.domain.end()), "0123456789ABCDEFGHIJ");
  EXPECT_EQ(values_.begin_size, 20u);
  EXPECT_EQ(values_.ends_ok, 1);
  EXPECT_FALSE(node_.sdo().busy());
}

TEST_F(SdoServerTest, ExpeditedDownloadAndUpload) {
  EXPECT_EQ(Send("2B171000E8030000"), Frames{"590#6017100000000000"});  // 0x1017 = 1000 ms
  EXPECT_EQ(node_.heartbeat_ms(), 1000);
  EXPECT_EQ(Send("4017100000000000"), Frames{"590#4B171000E8030000"});
  // Wrong size for a U16: 4 bytes is too long (0x06070012), 1 byte too short (0x06070013).
  EXPECT_EQ(Send("23171000E8030000"), Frames{"590#8017100012000706"});
  EXPECT_EQ(Send("2F171000E8000000"), Frames{"590#8017100013000706"});
  EXPECT_EQ(node_.heartbeat_ms(), 1000);
  // Read-only, write-only, missing object, missing sub-index.
  EXPECT_EQ(Send("2300100001000000"), Frames{"590#8000100002000106"});
  EXPECT_EQ(Send("4010210000000000"), Frames{"590#8010210001000106"});
  EXPECT_EQ(Send("4000300000000000"), Frames{"590#8000300000000206"});
  EXPECT_EQ(Send("4018100900000000"), Frames{"590#8018100911000906"});
  // Unknown command specifier.
  EXPECT_EQ(Send("E000000000000000"),
            (Frames{"090#11FF110100040500", "090#0000000000000000", "590#8000000001000405"}));
}

TEST_F(SdoServerTest, SegmentedUploadOfAString) {
  values_.values[ObjectId::kDeviceName] = {'v', 'o', 'l', 'c', 'o', 'm', 'p', '-', 'X'};
  EXPECT_EQ(Send("4008100000000000"), Frames{"590#4108100009000000"});
  EXPECT_EQ(Send("6000000000000000"), Frames{"590#00766F6C636F6D70"});
  EXPECT_EQ(Send("7000000000000000"), Frames{"590#1B2D580000000000"});  // 2 bytes, last
  // Toggle error.
  EXPECT_EQ(Send("4008100000000000"), Frames{"590#4108100009000000"});
  EXPECT_EQ(Send("7000000000000000"),
            (Frames{"090#11FF110000030500", "090#0000000000000000", "590#8008100000000305"}));
}

TEST_F(SdoServerTest, SegmentedDownloadOfADomain) {
  EXPECT_EQ(Send("210021000A000000"), Frames{"590#6000210000000000"});
  EXPECT_EQ(Send("0041424344454647"), Frames{"590#2000000000000000"});
  EXPECT_EQ(Send("1948494A00000000"), Frames{"590#3000000000000000"});  // 3 bytes, last
  EXPECT_EQ(std::string(values_.domain.begin(), values_.domain.end()), "ABCDEFGHIJ");
  EXPECT_EQ(values_.ends_ok, 1);
}

TEST_F(SdoServerTest, BlockDownloadLostSegmentIsAcknowledgedEarlyAndResent) {
  Send("C600210014000000");
  Send("0130313233343536");
  // Segment 2 lost: 3 arrives out of sequence -> ack with ackseq 1 at once.
  EXPECT_EQ(Send("8345464748494A00"), Frames{"590#A2017F0000000000"});
  // The client resends from byte 7, renumbered from 1.
  EXPECT_EQ(Send("0137383941424344"), Frames{});
  EXPECT_EQ(Send("8245464748494A00"), Frames{"590#A2027F0000000000"});
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(std::string(values_.domain.begin(), values_.domain.end()), "0123456789ABCDEFGHIJ");
}

TEST_F(SdoServerTest, BlockDownloadDuplicateSegmentIsIgnored) {
  Send("C600210014000000");
  Send("0130313233343536");
  EXPECT_EQ(Send("0130313233343536"), Frames{});  // duplicate of 1
  Send("0237383941424344");
  EXPECT_EQ(Send("8345464748494A00"), Frames{"590#A2037F0000000000"});
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(values_.domain.size(), 20u);
}

TEST_F(SdoServerTest, BlockDownloadLostTailIsReacknowledgedAfterSilence) {
  Send("C600210014000000");
  Send("0130313233343536");
  Send("0237383941424344");
  // Segment 3 (the last) lost; after the gap timeout the server acks what it has.
  EXPECT_EQ(Drain(), Frames{});
  Advance(150);
  EXPECT_EQ(Drain(), Frames{"590#A2027F0000000000"});
  EXPECT_EQ(Send("8145464748494A00"), Frames{"590#A2017F0000000000"});
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(values_.domain.size(), 20u);
}

TEST_F(SdoServerTest, BlockDownloadLostFinalAckIsRepeated) {
  Send("C600210014000000");
  Send("0130313233343536");
  Send("0237383941424344");
  Send("8345464748494A00");
  // The client did not get the ack and repeats the last segment.
  EXPECT_EQ(Send("8345464748494A00"), Frames{"590#A2037F0000000000"});
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#A100000000000000"});
}

TEST_F(SdoServerTest, BlockDownloadWrongCrcAborts) {
  Send("C600210014000000");
  Send("0130313233343536");
  Send("0237383941424344");
  Send("8345464748494A00");
  // The abort, preceded by the EMCY reporting the failed transfer (0xFF11, communication error,
  // abort code in bytes 3-6) and the "errors cleared" EMCY.
  EXPECT_EQ(Send("C5F1350000000000"),
            (Frames{"090#11FF110400040500", "090#0000000000000000", "590#8000210004000405"}));
  EXPECT_EQ(values_.ends_failed, 1);
  EXPECT_EQ(node_.sdo().last_abort(), canopen::SdoAbort::kCrc);
}

TEST_F(SdoServerTest, BlockDownloadSizeMismatchAborts) {
  // Announced 21 bytes, sent 20.
  Send("C600210015000000");
  Send("0130313233343536");
  Send("0237383941424344");
  Send("8345464748494A00");
  EXPECT_EQ(Send("C5F1340000000000"), Frames{"590#8000210013000706"});
  // Announced 10 bytes, sent 20: refused as soon as the data overflows (segment 2 is delivered
  // when segment 3 shows it was not the last).
  Send("C60021000A000000");
  Send("0130313233343536");
  EXPECT_EQ(Send("0237383941424344"), Frames{});
  EXPECT_EQ(Send("8345464748494A00"), Frames{"590#8000210012000706"});
  EXPECT_EQ(values_.ends_failed, 2);
}

TEST_F(SdoServerTest, IdleTransferTimesOut) {
  Send("C600210014000000");
  Send("0130313233343536");
  Advance(150);  // re-ack of the partial sub-block
  Drain();
  Advance(1000);
  EXPECT_EQ(Drain(),
            (Frames{"090#11FF110000040500", "090#0000000000000000", "590#8000210000000405"}));
  EXPECT_EQ(values_.ends_failed, 1);
  EXPECT_FALSE(node_.sdo().busy());
}

TEST_F(SdoServerTest, ClientAbortMidBlockEndsTheTransferSilently) {
  Send("C600210014000000");
  Send("0130313233343536");
  EXPECT_EQ(Send("8000210000000000"), Frames{});
  EXPECT_EQ(values_.ends_failed, 1);
  EXPECT_FALSE(node_.sdo().busy());
  // A new transfer works afterwards.
  EXPECT_EQ(Send("4017100000000000").size(), 1u);
}

// A client's abort is the client's finding, whatever its code: its own timeout (0x05040000) or
// CRC check (0x05040004) is no error of this node. The application hears the code and that the
// client sent it; no EMCY, nothing in 0x1001 / 0x1003. The same codes sent by the node (it timed
// the transfer out, the CRC it computed differs) are reported by EMCY 0xFF11.
TEST_F(SdoServerTest, AClientsAbortRaisesNoEmcyWhateverItsCode) {
  for (const char* abort : {"8000210000000405", "8000210004000405", "8000210021000008"}) {
    EXPECT_EQ(Send("C600210014000000"), Frames{"590#A40021007F000000"});
    EXPECT_EQ(Send("0130313233343536"), Frames{});
    EXPECT_EQ(Send(abort), Frames{}) << abort;
    EXPECT_EQ(values_.last_end_origin, canopen::AbortOrigin::kClient) << abort;
    EXPECT_EQ(node_.sdo().last_abort_origin(), canopen::AbortOrigin::kClient);
    Advance(200);  // the discard window closes; still nothing to send
    EXPECT_EQ(Drain(), Frames{}) << abort;
  }
  EXPECT_EQ(values_.last_end, canopen::SdoAbort::kLocalControl);
  EXPECT_EQ(values_.ends_failed, 3);
  EXPECT_EQ(node_.error_register(), 0);
  EXPECT_EQ(Send("4003100000000000"), Frames{"590#4F03100000000000"});  // 0x1003: no history
  // The node's own timeout: reported.
  Send("C600210014000000");
  Send("0130313233343536");
  Advance(150);
  Drain();
  Advance(1000);
  EXPECT_EQ(Drain(),
            (Frames{"090#11FF110000040500", "090#0000000000000000", "590#8000210000000405"}));
  EXPECT_EQ(values_.last_end_origin, canopen::AbortOrigin::kServer);
}

// A fixed-size value written with the wrong length is refused with 0x06070012 (too long) or
// 0x06070013 (too short) on every download path, never the generic 0x06070010; with the size
// announced, at the initiate frame.
TEST_F(SdoServerTest, LengthErrorsAreTooLongOrTooShortOnEveryWritePath) {
  // Expedited without the size (e = 1, s = 0): the object's own size is taken.
  EXPECT_EQ(Send("22171000F4010000"), Frames{"590#6017100000000000"});
  EXPECT_EQ(node_.heartbeat_ms(), 500);
  // Segmented, size announced: 4 and 1 bytes for the U16 0x1017.
  EXPECT_EQ(Send("2117100004000000"), Frames{"590#8017100012000706"});
  EXPECT_EQ(Send("2117100001000000"), Frames{"590#8017100013000706"});
  // Segmented without the size: 3 bytes in the last segment are too long, 1 too short.
  EXPECT_EQ(Send("2017100000000000"), Frames{"590#6017100000000000"});
  EXPECT_EQ(Send("09E8030000000000"), Frames{"590#8017100012000706"});
  EXPECT_EQ(Send("2017100000000000"), Frames{"590#6017100000000000"});
  EXPECT_EQ(Send("0DE8000000000000"), Frames{"590#8017100013000706"});
  // Block, size announced: refused at the initiate frame.
  EXPECT_EQ(Send("C617100004000000"), Frames{"590#8017100012000706"});
  EXPECT_EQ(Send("C617100001000000"), Frames{"590#8017100013000706"});
  // Block without the size or CRC (C0): one segment of 7 bytes is too long at once; 1 byte (6
  // unused) too short at the end frame.
  EXPECT_EQ(Send("C017100000000000"), Frames{"590#A01710007F000000"});
  EXPECT_EQ(Send("81E8030000000000"), Frames{"590#A2017F0000000000"});
  EXPECT_EQ(Send("C100000000000000"), Frames{"590#8017100012000706"});
  EXPECT_EQ(Send("C017100000000000"), Frames{"590#A01710007F000000"});
  EXPECT_EQ(Send("81E8000000000000"), Frames{"590#A2017F0000000000"});
  EXPECT_EQ(Send("D900000000000000"), Frames{"590#8017100013000706"});
  // The right length on the block path works.
  EXPECT_EQ(Send("C017100000000000"), Frames{"590#A01710007F000000"});
  EXPECT_EQ(Send("81E8030000000000"), Frames{"590#A2017F0000000000"});
  EXPECT_EQ(Send("D500000000000000"), Frames{"590#A100000000000000"});
  EXPECT_EQ(node_.heartbeat_ms(), 1000);
  // Every abort above was the node's finding about the request: EMCY only for protocol aborts.
  EXPECT_EQ(node_.error_register(), 0);
}

// A block segment as CiA 301 7.2.4.3.14 lays it out: byte 0 = c << 7 | seqno, then 7 data bytes
// (here the sequence number in each, to tell them apart).
std::string Segment(int seq, bool last = false) {
  char b[17];
  std::snprintf(b, sizeof b, "%02X%02X%02X%02X%02X%02X%02X%02X", (last ? 0x80 : 0) | seq, seq, seq,
                seq, seq, seq, seq, seq);
  return b;
}

// The server aborts in the middle of a sub-block (the application refuses the data): the client
// keeps sending the sub-block until it reads the abort. Those segments are dropped silently, not
// answered each as a new request with an abort (and an EMCY).
TEST_F(SdoServerTest, SegmentsInFlightAfterTheServersAbortAreDiscardedSilently) {
  // 2 full sub-blocks of 127 segments: 1778 bytes (0x06F2), CRC on.
  EXPECT_EQ(Send("C6002100F2060000"), Frames{"590#A40021007F000000"});
  for (int seq = 1; seq <= 63; ++seq) ASSERT_EQ(Send(Segment(seq)), Frames{}) << seq;
  values_.fail_domain_data_with = canopen::SdoAbort::kHardware;
  // Segment 64 shows 63 was not the last: 63 is delivered and refused (0x06060000).
  EXPECT_EQ(Send(Segment(64)), Frames{"590#8000210000000606"});
  for (int seq = 65; seq <= 127; ++seq) ASSERT_EQ(Send(Segment(seq)), Frames{}) << seq;
  EXPECT_EQ(node_.sdo().aborts(), 1u);
  EXPECT_EQ(node_.emcy_sent(), 0u);  // 0x06060000 is a refusal, not a protocol failure
  EXPECT_EQ(values_.ends_failed, 1);
  EXPECT_EQ(values_.last_end, canopen::SdoAbort::kHardware);
  // The next request is served.
  EXPECT_EQ(Send("4017100000000000"), Frames{"590#4B17100000000000"});
}

// A segment still in flight may look like a request: 0x22 is an expedited download, and these
// data bytes would write 0x1017 = 5. Dropped, it writes nothing.
TEST_F(SdoServerTest, ASegmentInFlightThatLooksLikeARequestIsNotServed) {
  EXPECT_EQ(Send("C6002100F2060000"), Frames{"590#A40021007F000000"});
  for (int seq = 1; seq <= 32; ++seq) ASSERT_EQ(Send(Segment(seq)), Frames{}) << seq;
  values_.fail_domain_data_with = canopen::SdoAbort::kHardware;
  EXPECT_EQ(Send(Segment(33)), Frames{"590#8000210000000606"});
  EXPECT_EQ(Send("2217100005000000"), Frames{});  // segment 34
  EXPECT_EQ(node_.heartbeat_ms(), 0);
  EXPECT_EQ(Send("4017100000000000"), Frames{"590#4B17100000000000"});
}

// The client aborts in the middle of a sub-block while segments are still queued behind its abort
// (a client sending from another thread): the rest of the sub-block, up to its last segment (the
// c bit, at the indicated size), is dropped silently.
TEST_F(SdoServerTest, SegmentsAfterTheClientsAbortAreDiscardedSilently) {
  EXPECT_EQ(Send("C600210014000000"), Frames{"590#A40021007F000000"});  // 20 bytes: 3 segments
  EXPECT_EQ(Send("0130313233343536"), Frames{});
  EXPECT_EQ(Send("8000210000000008"), Frames{});  // client abort, 0x08000000
  EXPECT_EQ(Send("0237383941424344"), Frames{});
  EXPECT_EQ(Send("8345464748494A00"), Frames{});
  EXPECT_EQ(values_.ends_failed, 1);
  EXPECT_EQ(values_.last_end, canopen::SdoAbort::kGeneral);
  // Past the sub-block's last segment a frame is a request again: a segment now is a protocol
  // error (0x05040001), reported by EMCY 0xFF11.
  EXPECT_EQ(Send("0300000000000000"),
            (Frames{"090#11FF110100040500", "090#0000000000000000", "590#8000000001000405"}));
}

// The window closes at the first frame that does not continue the sub-block (a new request, served)
// and after 100 ms of silence (the block gap time).
TEST_F(SdoServerTest, DiscardingEndsAtANewRequestOrAfterSilence) {
  EXPECT_EQ(Send("C6002100F2060000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Send(Segment(1)), Frames{});
  EXPECT_EQ(Send("8000210000000008"), Frames{});  // client abort
  EXPECT_EQ(Send("4017100000000000"), Frames{"590#4B17100000000000"});
  EXPECT_EQ(Send(Segment(2)),
            (Frames{"090#11FF110100040500", "090#0000000000000000", "590#8002020201000405"}));
  // Again, with silence after the abort.
  EXPECT_EQ(Send("C6002100F2060000"), Frames{"590#A40021007F000000"});
  EXPECT_EQ(Send(Segment(1)), Frames{});
  EXPECT_EQ(Send("8000210000000008"), Frames{});
  Advance(100);
  EXPECT_EQ(Send(Segment(2)),
            (Frames{"090#11FF110100040500", "090#0000000000000000", "590#8002020201000405"}));
}

TEST_F(SdoServerTest, MalformedFramesAreCountedAndIgnored) {
  CanFrame short_frame = F(0x610, "4017100000");
  node_.OnFrame(short_frame, now_);
  EXPECT_EQ(Drain(), Frames{});
  EXPECT_EQ(node_.malformed(), 1u);
}

TEST_F(SdoServerTest, BlockUploadWithRetransmission) {
  values_.domain_readback.resize(30);
  for (size_t i = 0; i < 30; ++i) values_.domain_readback[i] = static_cast<uint8_t>('a' + i % 26);
  // Initiate: CRC on, block size 3.
  EXPECT_EQ(Send("A400210003000000"), Frames{"590#C60021001E000000"});
  Frames segs = Send("A300000000000000");
  ASSERT_EQ(segs.size(), 3u);
  EXPECT_EQ(segs[0], "590#0161626364656667");
  // Client acks only 1 of 3: the server resends from byte 7 with sequence 1.
  segs = Send("A201030000000000");
  ASSERT_EQ(segs.size(), 3u);
  EXPECT_EQ(segs[0], "590#0168696A6B6C6D6E");
  // 7 + 21 = 28 bytes confirmed; the last 2 bytes go in one final segment (c = 1).
  EXPECT_EQ(Send("A203030000000000"), Frames{"590#8163640000000000"});
  const std::vector<uint8_t>& d = values_.domain_readback;
  const uint16_t crc = canopen::Crc16Update(0, d.data(), d.size());
  char end[32];
  std::snprintf(end, sizeof end, "590#D5%02X%02X0000000000", crc & 0xFF, crc >> 8);
  // End: 5 unused bytes in the last segment (0xC1 | 5 << 2), then the CRC.
  EXPECT_EQ(Send("A201030000000000"), Frames{end});
  EXPECT_EQ(Send("A100000000000000"), Frames{});
  EXPECT_FALSE(node_.sdo().busy());
}

}  // namespace
}  // namespace volcomp
