// The PC tool's SDO client against frames written from CiA 301 7.2.4.3: an answer is taken only
// when it names the object asked for (index and sub-index, bytes 1-3, of initiate responses and
// aborts); a late answer to an earlier request is ignored, never returned as the value.
#include "volcomp/canopen_client/sdo_client.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "frames.hpp"
#include "volcomp/canopen_client/sdo_runner.hpp"

namespace volcomp::canopen_client {
namespace {

using testing::F;
using testing::ToString;
using Frames = std::vector<std::string>;

constexpr uint8_t kNode = 0x10;

Frames Sent(SdoClient& c) {
  Frames out;
  CanFrame f;
  while (c.PopTx(&f)) out.push_back(ToString(f));
  return out;
}

// `volcomp sdo read 2140:1` while the answer to an earlier read of 0x1000 is still on its way.
TEST(SdoClientMultiplexer, AStaleUploadAnswerForAnotherObjectIsIgnored) {
  SdoClient c(kNode);
  c.StartRead(0x2140, 1);
  EXPECT_EQ(Sent(c), Frames{"610#4040210100000000"});
  c.OnFrame(F(0x590, "4300100000000000"), 1000);  // 0x1000:00 = 0: not ours
  EXPECT_FALSE(c.done());
  EXPECT_EQ(Sent(c), Frames{});                   // no abort either: the transfer goes on
  c.OnFrame(F(0x590, "4B00100100000000"), 1000);  // 0x1000:01: another sub-index
  c.OnFrame(F(0x590, "4341210178563412"), 1000);  // 0x2141:01: another index
  EXPECT_FALSE(c.done());
  c.OnFrame(F(0x590, "4340210178563412"), 1000);  // 0x2140:01
  ASSERT_TRUE(c.done());
  ASSERT_TRUE(c.result().ok()) << c.result().error().message;
  EXPECT_EQ(*c.result(), (std::vector<uint8_t>{0x78, 0x56, 0x34, 0x12}));
}

// Ignoring is not progress: with only stale answers the request times out.
TEST(SdoClientMultiplexer, OnlyStaleAnswersEndInATimeout) {
  SdoClient::Options o;
  o.timeout_ms = 100;
  SdoClient c(kNode, o);
  c.StartRead(0x2140, 1);
  Sent(c);
  c.Poll(0);
  for (uint64_t t_us = 0; t_us <= 200000 && !c.done(); t_us += 10000) {
    c.OnFrame(F(0x590, "4300100000000000"), t_us);
    c.Poll(t_us);
  }
  ASSERT_TRUE(c.done());
  ASSERT_FALSE(c.result().ok());
  EXPECT_EQ(c.result().error().abort, canopen::SdoAbort::kTimeout);
  EXPECT_FALSE(c.result().error().by_server);
  // Nothing answered: a communication failure (exit 3 in the tool), not a refusal.
  EXPECT_EQ(c.result().error().code, Error::kCommunication);
  EXPECT_EQ(c.result().error().message,
            "no response from node 16 (sent abort 0x05040000: SDO protocol timed out)");
  EXPECT_EQ(Sent(c), Frames{"610#8040210100000405"});
}

TEST(SdoClientMultiplexer, AnAbortForAnotherObjectDoesNotEndTheTransfer) {
  SdoClient c(kNode);
  c.StartRead(0x2140, 1);
  Sent(c);
  c.OnFrame(F(0x590, "8000300000000206"), 1000);  // 0x3000:00 does not exist: not ours
  EXPECT_FALSE(c.done());
  c.OnFrame(F(0x590, "8040210111000906"), 1000);  // 0x2140:01: 0x06090011
  ASSERT_TRUE(c.done());
  ASSERT_FALSE(c.result().ok());
  EXPECT_TRUE(c.result().error().by_server);
  EXPECT_EQ(c.result().error().abort, canopen::SdoAbort::kNoSubIndex);
  EXPECT_EQ(c.result().error().code, Error::kTransferAborted);
  EXPECT_EQ(c.result().error().message,
            "node 16 refused 2140:01: abort 0x06090011 (sub-index does not exist)");
}

TEST(SdoClientMultiplexer, DownloadAnswersForAnotherObjectAreIgnored) {
  // Expedited: 0x2121:00 = 1 (one byte).
  SdoClient c(kNode);
  c.StartWrite(0x2121, 0, {0x01});
  EXPECT_EQ(Sent(c), Frames{"610#2F21210001000000"});
  c.OnFrame(F(0x590, "6017100000000000"), 1000);  // the answer to a write of 0x1017
  EXPECT_FALSE(c.done());
  c.OnFrame(F(0x590, "6021210000000000"), 1000);
  ASSERT_TRUE(c.done());
  EXPECT_TRUE(c.result().ok());

  // Block: 0x2100:00, 8 bytes.
  SdoClient b(kNode);
  b.StartWrite(0x2100, 0, {1, 2, 3, 4, 5, 6, 7, 8});
  EXPECT_EQ(Sent(b), Frames{"610#C600210008000000"});
  b.OnFrame(F(0x590, "A40020007F000000"), 1000);  // 0x2000:00
  EXPECT_EQ(Sent(b), Frames{});
  b.OnFrame(F(0x590, "A40021007F000000"), 1000);
  EXPECT_EQ(Sent(b), (Frames{"610#0101020304050607", "610#8208000000000000"}));
}

TEST(SdoClientMultiplexer, BlockUploadAnswerForAnotherObjectIsIgnored) {
  SdoClient c(kNode);
  c.StartRead(0x2100, 0, true);
  EXPECT_EQ(Sent(c), Frames{"610#A40021007F000000"});
  c.OnFrame(F(0x590, "C600200003000000"), 1000);  // 0x2000:00
  EXPECT_EQ(Sent(c), Frames{});
  c.OnFrame(F(0x590, "C600210003000000"), 1000);  // 0x2100:00, 3 bytes
  EXPECT_EQ(Sent(c), Frames{"610#A300000000000000"});
  c.OnFrame(F(0x590, "81AABBCC00000000"), 1000);  // segment 1, last
  EXPECT_EQ(Sent(c), Frames{"610#A2017F0000000000"});
  // End: 4 unused bytes (0xC1 | 4 << 2), CRC-16/XMODEM of AA BB CC = 0xA06A (binascii.crc_hqx).
  c.OnFrame(F(0x590, "D16AA00000000000"), 1000);
  EXPECT_EQ(Sent(c), Frames{"610#A100000000000000"});
  ASSERT_TRUE(c.done());
  ASSERT_TRUE(c.result().ok()) << c.result().error().message;
  EXPECT_EQ(*c.result(), (std::vector<uint8_t>{0xAA, 0xBB, 0xCC}));
}

// A frame that fits neither the state nor another object's answer still aborts (0x05040001).
TEST(SdoClientMultiplexer, AnUnexpectedAnswerForThisObjectAborts) {
  SdoClient c(kNode);
  c.StartRead(0x2140, 1);
  Sent(c);
  c.OnFrame(F(0x590, "6040210100000000"), 1000);  // a download answer to an upload
  ASSERT_TRUE(c.done());
  EXPECT_EQ(canopen_client::AbortOf(c.result()), canopen::SdoAbort::kCommand);
  EXPECT_EQ(c.result().error().code, Error::kTransferAborted);
  EXPECT_EQ(Sent(c), Frames{"610#8040210101000405"});
}

// Before it finishes a transfer has no result (a failure that says so, never a value).
TEST(SdoClientMultiplexer, ARunningTransferHasNoValue) {
  SdoClient c(kNode);
  c.StartRead(0x2140, 1);
  ASSERT_FALSE(c.result().ok());
  EXPECT_EQ(c.result().error().code, Error::kNotReady);
  EXPECT_EQ(Sent(c), Frames{"610#4040210100000000"});
  // The link failed: the transfer ends with its failure and sends nothing more (no abort).
  c.Abandon(Failure{Error::kCommunication, "slcan-tcp:h:1: connection closed by the peer"});
  ASSERT_TRUE(c.done());
  EXPECT_EQ(Sent(c), Frames{});
  EXPECT_EQ(c.result().error().code, Error::kCommunication);
  EXPECT_EQ(c.result().error().abort, canopen::SdoAbort::kNone);
}

// A scripted link: `inbox` is delivered in order; `on_send` may queue answers.
struct ScriptedLink {
  std::vector<CanFrame> inbox;
  Frames sent;
  uint64_t now_us = 0;
  std::function<void(const CanFrame&)> on_send;
  FrameLink link() {
    FrameLink l;
    l.send = [this](const CanFrame& f) {
      sent.push_back(ToString(f));
      if (on_send) on_send(f);
      return Outcome::Ok();
    };
    l.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
      now_us += 100;
      if (inbox.empty()) {
        now_us += timeout_us;
        return std::optional<CanFrame>();
      }
      const CanFrame f = inbox.front();
      inbox.erase(inbox.begin());
      return std::optional<CanFrame>(f);
    };
    l.now_us = [this] { return now_us; };
    return l;
  }
};

// The blocking read the `volcomp sdo read` command uses, over a link that first delivers the late
// answer of an earlier request.
TEST(SdoClientMultiplexer, ReadU32ReturnsTheValueOfTheObjectAsked) {
  ScriptedLink s;
  s.inbox = {F(0x590, "4300100000000000")};
  s.on_send = [&s](const CanFrame& f) {
    if (f.data[0] == 0x40) s.inbox.push_back(F(0x590, "4340210107000000"));
  };
  const SdoExpected<uint32_t> r = ReadU32(s.link(), kNode, 0x2140, 1);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(*r, 7u);
  EXPECT_EQ(s.sent, Frames{"610#4040210100000000"});
}

// A link that fails ends the access with the link's failure (no abort is sent on a dead link).
TEST(SdoClientMultiplexer, ALinkFailureEndsTheAccessWithItsMessage) {
  FrameLink link;
  int sent = 0;
  link.send = [&](const CanFrame&) {
    ++sent;
    return Outcome::Ok();
  };
  link.receive = [](uint64_t) -> Expected<std::optional<CanFrame>> {
    return Fail(Error::kCommunication, "slcan-tcp:h:1: connection closed by the peer");
  };
  link.now_us = [] { return uint64_t{0}; };
  const SdoOutcome w = WriteU32(link, kNode, 0x2101, 0, 4, 1);
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.error().code, Error::kCommunication);
  EXPECT_EQ(w.error().message, "slcan-tcp:h:1: connection closed by the peer");
  EXPECT_EQ(w.error().abort, canopen::SdoAbort::kNone);
  EXPECT_EQ(sent, 1);

  link.send = [](const CanFrame&) -> Outcome {
    return Fail(Error::kCommunication, "socketcan:can0: controller is bus-off; frame not sent");
  };
  const SdoExpected<uint32_t> r = ReadU32(link, kNode, 0x2104, 0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kCommunication);
  EXPECT_EQ(r.error().message, "socketcan:can0: controller is bus-off; frame not sent");
}

// A value that is not 1..4 bytes is no number: a failure of its own (no abort).
TEST(SdoClientMultiplexer, ReadU32RefusesAnAnswerOfTheWrongSize) {
  ScriptedLink s;
  // Segmented upload of 5 bytes: initiate (size 5), then one last segment of 5 bytes.
  s.on_send = [&s](const CanFrame& f) {
    if (f.data[0] == 0x40) s.inbox.push_back(F(0x590, "4140210105000000"));
    if (f.data[0] == 0x60) s.inbox.push_back(F(0x590, "0501020304050000"));
  };
  const SdoExpected<uint32_t> r = ReadU32(s.link(), kNode, 0x2140, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInputInvalid);
  EXPECT_EQ(r.error().abort, canopen::SdoAbort::kNone);
  EXPECT_EQ(r.error().message, "unexpected value size 5");
}

}  // namespace
}  // namespace volcomp::canopen_client
