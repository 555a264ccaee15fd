// SLCAN codec: encoding, parsing of every command/response, malformed lines, decoder framing.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "can_frames.hpp"
#include "volcomp/can/slcan.hpp"

namespace volcomp::slcan {
namespace {

using namespace std::string_literals;

using testing::Frame;

std::string EncodeToString(const Message& m) {
  char buf[kMaxEncodedLength];
  const size_t n = Encode(m, buf, sizeof buf);
  return std::string(buf, n);
}

std::string EncodeFrameToString(const CanFrame& f) {
  char buf[kMaxEncodedLength];
  return std::string(buf, EncodeFrame(f, buf, sizeof buf));
}

// Feeds a whole string, returns every message.
std::vector<Message> DecodeAll(Role role, const std::string& bytes) {
  Decoder d(role);
  std::vector<Message> out;
  for (char c : bytes) {
    Message m;
    if (d.Feed(static_cast<uint8_t>(c), &m)) out.push_back(m);
  }
  return out;
}

Message One(Role role, const std::string& line) {
  auto all = DecodeAll(role, line);
  EXPECT_EQ(all.size(), 1u) << line;
  return all.empty() ? Message() : all[0];
}

TEST(CanIoSlcanCodec, EncodesFramesInUppercaseHex) {
  EXPECT_EQ(EncodeFrameToString(Frame(0x123, false, false, {0x11, 0x22, 0xAB})), "t12331122AB\r");
  EXPECT_EQ(EncodeFrameToString(Frame(0x1ABCDEF0, true, false, {0xFF})), "T1ABCDEF01FF\r");
  EXPECT_EQ(EncodeFrameToString(Frame(0x7FF, false, true, {0, 0})), "r7FF2\r");
  EXPECT_EQ(EncodeFrameToString(Frame(0x1, true, true, {})), "R000000010\r");
  EXPECT_EQ(EncodeFrameToString(Frame(0x0, false, false, {})), "t0000\r");
  EXPECT_EQ(EncodeFrameToString(Frame(0x601, false, false, {0x40, 0, 0x10, 0, 0, 0, 0, 0})),
            "t60184000100000000000\r");
}

TEST(CanIoSlcanCodec, EncodeRefusesInvalidFramesAndSmallBuffers) {
  CanFrame bad_id = Frame(0x800, false, false, {});
  char buf[kMaxEncodedLength];
  EXPECT_EQ(EncodeFrame(bad_id, buf, sizeof buf), 0u);
  CanFrame bad_dlc = Frame(0x100, false, false, {});
  bad_dlc.dlc = 9;
  EXPECT_EQ(EncodeFrame(bad_dlc, buf, sizeof buf), 0u);
  EXPECT_EQ(EncodeFrame(Frame(0x1FFFFFFF, true, false, {}), buf, sizeof buf), 11u);
  CanFrame ext_bad = Frame(0x20000000, true, false, {});
  EXPECT_EQ(EncodeFrame(ext_bad, buf, sizeof buf), 0u);

  const CanFrame f = Frame(0x123, false, false, {1, 2});
  EXPECT_EQ(EncodeFrame(f, buf, 10), 10u);  // "t12320102\r" is exactly 10 bytes
  EXPECT_EQ(EncodeFrame(f, buf, 9), 0u);
  EXPECT_EQ(EncodeFrame(f, nullptr, 100), 0u);
  EXPECT_EQ(EncodeFrame(f, buf, 0), 0u);

  // The longest line fits kMaxEncodedLength exactly.
  Message m;
  m.kind = Kind::kFrame;
  m.frame = Frame(0x1FFFFFFF, true, false, {1, 2, 3, 4, 5, 6, 7, 8});
  m.has_timestamp = true;
  m.timestamp_ms = 0xEA5F;
  EXPECT_EQ(EncodeToString(m), "T1FFFFFFF80102030405060708EA5F\r");
  EXPECT_EQ(EncodeToString(m).size(), kMaxEncodedLength);
}

TEST(CanIoSlcanCodec, FrameRoundTripRandom) {
  std::mt19937 rng(3);
  std::string stream;
  std::vector<CanFrame> sent;
  for (int i = 0; i < 2000; ++i) {
    CanFrame f;
    f.extended = (rng() & 1) != 0;
    f.rtr = (rng() % 5) == 0;
    f.id = static_cast<uint32_t>(rng()) & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
    f.dlc = static_cast<uint8_t>(rng() % 9);
    for (auto& d : f.data) d = static_cast<uint8_t>(rng());
    sent.push_back(f);
    stream += EncodeFrameToString(f);
  }
  for (Role role : {Role::kDevice, Role::kHost}) {
    auto got = DecodeAll(role, stream);
    ASSERT_EQ(got.size(), sent.size());
    for (size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].kind, Kind::kFrame);
      EXPECT_EQ(got[i].frame, sent[i]) << i;
      EXPECT_FALSE(got[i].has_timestamp);
    }
  }
}

TEST(CanIoSlcanCodec, ParsesTimestampsAndLowercase) {
  Message m = One(Role::kHost, "t1232aabb1234\r");
  ASSERT_EQ(m.kind, Kind::kFrame);
  EXPECT_EQ(m.frame, Frame(0x123, false, false, {0xAA, 0xBB}));
  EXPECT_TRUE(m.has_timestamp);
  EXPECT_EQ(m.timestamp_ms, 0x1234);
  // The kernel's SLC_MTU example line.
  m = One(Role::kHost, "T1111222281122334455667788EA5F\r");
  ASSERT_EQ(m.kind, Kind::kFrame);
  EXPECT_EQ(m.frame.id, 0x11112222u);
  EXPECT_EQ(m.timestamp_ms, 0xEA5F);
  // Remote frame + timestamp.
  m = One(Role::kDevice, "r1238ffff\r");
  ASSERT_EQ(m.kind, Kind::kFrame);
  EXPECT_TRUE(m.frame.rtr);
  EXPECT_EQ(m.frame.dlc, 8);
  EXPECT_EQ(m.timestamp_ms, 0xFFFF);
}

TEST(CanIoSlcanCodec, ParsesEveryCommand) {
  struct Case {
    const char* line;
    Kind kind;
    uint32_t value;
  };
  const Case cases[] = {
      {"O", Kind::kOpen, 0},
      {"L", Kind::kListenOnly, 0},
      {"C", Kind::kClose, 0},
      {"S0", Kind::kBitrate, 0},
      {"S8", Kind::kBitrate, 8},
      {"S9", Kind::kBitrate, 9},
      {"s031C", Kind::kBtr, 0x031C},
      {"F", Kind::kStatusRequest, 0},
      {"V", Kind::kVersionRequest, 0},
      {"v", Kind::kDetailRequest, 0},
      {"N", Kind::kSerialRequest, 0},
      {"Z0", Kind::kTimestamps, 0},
      {"Z1", Kind::kTimestamps, 1},
      {"X0", Kind::kAutoPoll, 0},
      {"X1", Kind::kAutoPoll, 1},
      {"M12345678", Kind::kAcceptCode, 0x12345678},
      {"mffffffff", Kind::kAcceptMask, 0xFFFFFFFF},
      {"U1", Kind::kUartRate, 1},
      {"P", Kind::kPollOne, 0},
      {"A", Kind::kPollAll, 0},
  };
  for (const Case& c : cases) {
    const Message m = One(Role::kDevice, std::string(c.line) + "\r");
    EXPECT_EQ(m.kind, c.kind) << c.line;
    EXPECT_EQ(m.value, c.value) << c.line;
    // And the encoder writes the same line back (hex in uppercase).
    Message e;
    e.kind = c.kind;
    e.value = c.value;
    std::string expect = std::string(c.line) + "\r";
    for (size_t i = 1; i < expect.size(); ++i) {
      if (expect[i] >= 'a' && expect[i] <= 'f') expect[i] = static_cast<char>(expect[i] - 32);
    }
    EXPECT_EQ(EncodeToString(e), expect);
  }
}

TEST(CanIoSlcanCodec, ParsesEveryResponse) {
  EXPECT_EQ(One(Role::kHost, "\r").kind, Kind::kOk);
  EXPECT_EQ(One(Role::kHost, "\a").kind, Kind::kError);
  EXPECT_EQ(One(Role::kHost, "z\r").kind, Kind::kTxAck);
  EXPECT_EQ(One(Role::kHost, "Z\r").kind, Kind::kTxAckExt);
  Message m = One(Role::kHost, "F2A\r");
  EXPECT_EQ(m.kind, Kind::kStatusReply);
  EXPECT_EQ(m.value, 0x2Au);
  m = One(Role::kHost, "V1013\r");
  EXPECT_EQ(m.kind, Kind::kVersionReply);
  EXPECT_STREQ(m.text, "1013");
  m = One(Role::kHost, "v1014\r");
  EXPECT_EQ(m.kind, Kind::kDetailReply);
  EXPECT_STREQ(m.text, "1014");
  m = One(Role::kHost, "NA1b2\r");
  EXPECT_EQ(m.kind, Kind::kSerialReply);
  EXPECT_STREQ(m.text, "A1b2");
  // Encoder side.
  Message e;
  e.kind = Kind::kError;
  EXPECT_EQ(EncodeToString(e), "\a");
  e.kind = Kind::kOk;
  EXPECT_EQ(EncodeToString(e), "\r");
  e.kind = Kind::kSerialReply;
  std::snprintf(e.text, sizeof e.text, "4242");
  EXPECT_EQ(EncodeToString(e), "N4242\r");
  e.kind = Kind::kStatusReply;
  e.value = 0x100;  // does not fit two digits
  EXPECT_EQ(EncodeToString(e), "");
  e.kind = Kind::kMalformed;
  EXPECT_EQ(EncodeToString(e), "");
}

TEST(CanIoSlcanCodec, RoleDecidesAmbiguousLetters) {
  EXPECT_EQ(One(Role::kHost, "Z\r").kind, Kind::kTxAckExt);
  EXPECT_EQ(One(Role::kDevice, "Z\r").error, ParseError::kBadLength);  // Z needs 0/1 from a host
  EXPECT_EQ(One(Role::kHost, "Z1\r").error, ParseError::kBadLength);
  EXPECT_EQ(One(Role::kDevice, "F\r").kind, Kind::kStatusRequest);
  EXPECT_EQ(One(Role::kHost, "F\r").error, ParseError::kBadLength);
  EXPECT_EQ(One(Role::kHost, "O\r").error, ParseError::kUnknownCommand);
}

TEST(CanIoSlcanCodec, MalformedLines) {
  struct Case {
    Role role;
    const char* line;
    ParseError error;
  };
  const Role D = Role::kDevice;
  const Role H = Role::kHost;
  const Case cases[] = {
      // Frames.
      {D, "t", ParseError::kBadLength},
      {D, "t12", ParseError::kBadLength},
      {D, "t123", ParseError::kBadLength},  // no length digit
      {D, "t1G30", ParseError::kBadHex},    // id
      {D, "t-120", ParseError::kBadHex},
      {D, "t8000", ParseError::kIdOutOfRange},  // 3 digits can say 0x800..0xFFF
      {D, "tFFF0", ParseError::kIdOutOfRange},
      {D, "T200000000", ParseError::kIdOutOfRange},
      {D, "TFFFFFFFF0", ParseError::kIdOutOfRange},
      {D, "T1234567", ParseError::kBadLength},  // short extended id, no length
      {D, "t1239", ParseError::kBadDlc},
      {D, "t123F", ParseError::kBadDlc},  // FD length codes are not classic
      {D, "t123:", ParseError::kBadDlc},
      {D, "t1232AA", ParseError::kBadLength},       // missing data
      {D, "t1232AABBC", ParseError::kBadLength},    // 1 extra digit
      {D, "t1232AABB12", ParseError::kBadLength},   // 2 extra digits
      {D, "t1232AABB123", ParseError::kBadLength},  // 3 extra digits
      {D, "t1232AABB12345", ParseError::kBadLength},
      {D, "t1232AAZZ", ParseError::kBadHex},  // data
      {D, "t1232 ABB", ParseError::kBadHex},
      {D, "t1230GGGG", ParseError::kBadHex},  // timestamp
      {D, "r12320", ParseError::kBadLength},  // remote frames carry no data
      {D, "r123200", ParseError::kBadLength},
      {H, "T12345678800112233445566", ParseError::kBadLength},
      // Commands.
      {D, "O1", ParseError::kBadLength},
      {D, "CC", ParseError::kBadLength},
      {D, "S", ParseError::kBadLength},
      {D, "SA", ParseError::kBadArgument},
      {D, "S10", ParseError::kBadLength},
      {D, "S-", ParseError::kBadArgument},
      {D, "Z2", ParseError::kBadArgument},
      {D, "X9", ParseError::kBadArgument},
      {D, "U:", ParseError::kBadArgument},
      {D, "s12", ParseError::kBadLength},
      {D, "s12G4", ParseError::kBadHex},
      {D, "s12345", ParseError::kBadLength},
      {D, "M123", ParseError::kBadLength},
      {D, "m1234567G", ParseError::kBadHex},
      {D, "x", ParseError::kUnknownCommand},
      {D, "\x80", ParseError::kUnknownCommand},
      {D, " O", ParseError::kUnknownCommand},
      {D, "z", ParseError::kUnknownCommand},  // a device response sent to a device
      // Responses.
      {H, "F", ParseError::kBadLength},
      {H, "F0", ParseError::kBadLength},
      {H, "FXX", ParseError::kBadHex},
      {H, "V12", ParseError::kBadLength},
      {H, "V123456", ParseError::kBadLength},
      {H, "V12 4", ParseError::kBadArgument},
      {H, "N\x01\x02\x03\x04", ParseError::kBadArgument},
      {H, "zz", ParseError::kBadLength},
      {H, "q", ParseError::kUnknownCommand},
  };
  for (const Case& c : cases) {
    const Message m = One(c.role, std::string(c.line) + "\r");
    EXPECT_EQ(m.kind, Kind::kMalformed) << c.line;
    EXPECT_EQ(m.error, c.error) << c.line;
  }
}

TEST(CanIoSlcanCodec, OverlongLineIsReportedOnceAndDecodingRecovers) {
  for (Role role : {Role::kDevice, Role::kHost}) {
    const std::string junk(kMaxLineLength + 1, 'A');
    auto got = DecodeAll(role, junk + "\r" + std::string(500, 'x') + "\rt1230\r");
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(got[0].error, ParseError::kLineTooLong);
    EXPECT_EQ(got[1].error, ParseError::kLineTooLong);
    EXPECT_EQ(got[2].kind, Kind::kFrame);
    // Exactly kMaxLineLength characters is still a line.
    got = DecodeAll(role, "T1FFFFFFF80102030405060708EA5F\r");
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].kind, Kind::kFrame);
  }
  EXPECT_EQ(ParseLine(Role::kDevice, "O", 1000).error, ParseError::kLineTooLong);
}

TEST(CanIoSlcanCodec, TerminatorsAndFiller) {
  // Device: leading and repeated CRs are skipped, BEL also ends a line, NUL and LF are ignored.
  auto got = DecodeAll(Role::kDevice, "\r\r\rC\r\nS8\aO\r\0\r"s);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].kind, Kind::kClose);
  EXPECT_EQ(got[1].kind, Kind::kBitrate);
  EXPECT_EQ(got[2].kind, Kind::kOpen);
  // Host: every CR alone is an OK, a BEL is an error even after a partial line.
  got = DecodeAll(Role::kHost, "\r\rz\rt12\a\a");
  ASSERT_EQ(got.size(), 5u);
  EXPECT_EQ(got[0].kind, Kind::kOk);
  EXPECT_EQ(got[1].kind, Kind::kOk);
  EXPECT_EQ(got[2].kind, Kind::kTxAck);
  EXPECT_EQ(got[3].kind, Kind::kError);
  EXPECT_EQ(got[4].kind, Kind::kError);
  // A partial line waits for its terminator; Reset() drops it.
  Decoder d(Role::kDevice);
  Message m;
  for (char c : std::string("t12")) EXPECT_FALSE(d.Feed(static_cast<uint8_t>(c), &m));
  d.Reset();
  for (char c : std::string("O")) EXPECT_FALSE(d.Feed(static_cast<uint8_t>(c), &m));
  ASSERT_TRUE(d.Feed('\r', &m));
  EXPECT_EQ(m.kind, Kind::kOpen);
}

TEST(CanIoSlcanCodec, RandomBytesNeverMisbehave) {
  std::mt19937 rng(5);
  const char alphabet[] = "tTrRsSOCLFVvNZXMmUPA0123456789abcdefABCDEFGz\r\a\r\r\x80 ";
  for (Role role : {Role::kDevice, Role::kHost}) {
    Decoder d(role);
    size_t messages = 0;
    for (int i = 0; i < 200000; ++i) {
      const uint8_t b = (rng() % 4 == 0)
                            ? static_cast<uint8_t>(rng())
                            : static_cast<uint8_t>(alphabet[rng() % (sizeof alphabet - 1)]);
      Message m;
      if (d.Feed(b, &m)) {
        ++messages;
        if (m.kind == Kind::kFrame) {
          ASSERT_TRUE(m.frame.valid());
          // Whatever parsed as a frame re-encodes to a line that parses to the same frame.
          char buf[kMaxEncodedLength];
          const size_t n = Encode(m, buf, sizeof buf);
          ASSERT_GT(n, 0u);
          const Message again = ParseLine(role, buf, n - 1);
          ASSERT_EQ(again.kind, Kind::kFrame);
          ASSERT_EQ(again.frame, m.frame);
        } else if (m.kind == Kind::kMalformed) {
          ASSERT_NE(m.error, ParseError::kNone);
        }
      }
    }
    EXPECT_GT(messages, 1000u);
  }
}

TEST(CanIoSlcanCodec, BitrateTable) {
  const uint32_t expected[] = {10000,  20000,  50000,  100000,  125000,
                               250000, 500000, 800000, 1000000, 83333};
  for (uint32_t n = 0; n < 10; ++n) {
    EXPECT_EQ(BitrateForIndex(n), expected[n]);
    EXPECT_EQ(IndexForBitrate(expected[n]), static_cast<int>(n));
  }
  EXPECT_EQ(BitrateForIndex(10), 0u);
  EXPECT_EQ(IndexForBitrate(750000), -1);  // python-can's S7 meaning; we use the standard 800k
  EXPECT_EQ(IndexForBitrate(0), -1);
}

}  // namespace
}  // namespace volcomp::slcan
