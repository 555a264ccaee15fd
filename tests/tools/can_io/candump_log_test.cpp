// candump -L log writer/reader and the LoggingTransport decorator.
#include "volcomp/can_io/candump_log.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <sstream>

#include "can_frames.hpp"
#include "volcomp/can_io/logging_transport.hpp"

namespace volcomp::can_io {
namespace {

using testing::Frame;

std::string Line(const CanFrame& f, uint64_t us, Direction d = Direction::kNone) {
  CandumpRecord r;
  r.timestamp_us = us;
  r.iface = "can0";
  r.frame = f;
  r.direction = d;
  return FormatCandumpLine(r);
}

TEST(CanIoCandump, FormatsLikeCandump) {
  EXPECT_EQ(Line(Frame(0x601, false, false, {0x40, 0x00, 0x10, 0x00, 0xAB, 0, 0, 0}),
                 1700000000123456ull),
            "(1700000000.123456) can0 601#40001000AB000000");
  EXPECT_EQ(Line(Frame(0x5, false, false, {}), 7), "(0.000007) can0 005#");
  EXPECT_EQ(Line(Frame(0x1ABCDEF0, true, false, {0x01}), 1000000, Direction::kTx),
            "(1.000000) can0 1ABCDEF0#01 T");
  EXPECT_EQ(Line(Frame(0x00000001, true, false, {}), 0, Direction::kRx),
            "(0.000000) can0 00000001# R");
  EXPECT_EQ(Line(Frame(0x710, false, true, {}), 0), "(0.000000) can0 710#R");
  EXPECT_EQ(Line(Frame(0x710, false, true, {}, 4), 0), "(0.000000) can0 710#R4");
}

TEST(CanIoCandump, ParsesCandumpAndPythonCanLines) {
  auto r = ParseCandumpLine("(1795301836.647088) vcan0 710#05 R");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->timestamp_us, 1795301836647088ull);
  EXPECT_EQ(r->iface, "vcan0");
  EXPECT_EQ(r->frame, Frame(0x710, false, false, {0x05}));
  EXPECT_EQ(r->direction, Direction::kRx);

  r = ParseCandumpLine("(0.000001) slcan0 1abcdef0#deadBEEF\r\n");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->frame.extended);
  EXPECT_EQ(r->frame, Frame(0x1ABCDEF0, true, false, {0xDE, 0xAD, 0xBE, 0xEF}));

  r = ParseCandumpLine("(5.500000) can0 123#R");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->frame.rtr);
  EXPECT_EQ(r->frame.dlc, 0);
  r = ParseCandumpLine("(5.500000) can0 123#R8");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->frame.dlc, 8);
  r = ParseCandumpLine("(5.500000)   can0   123#11.22.33");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->frame, Frame(0x123, false, false, {0x11, 0x22, 0x33}));
}

TEST(CanIoCandump, RejectsMalformedLines) {
  const char* bad[] = {
      "",
      "(1.000000) can0",
      "1.000000 can0 123#00",
      "(1.000000 can0 123#00",
      "(1.00000) can0 123#00",    // 5 fraction digits
      "(1.0000000) can0 123#00",  // 7
      "(x.000000) can0 123#00",
      "(1.000000) can0 12#00",
      "(1.000000) can0 1234#00",
      "(1.000000) can0 800#00",
      "(1.000000) can0 20000000#00",
      "(1.000000) can0 12G#00",
      "(1.000000) can0 123",
      "(1.000000) can0 123#0",
      "(1.000000) can0 123#001122334455667788",
      "(1.000000) can0 123#0G",
      "(1.000000) can0 123##1001122",
      "(1.000000) can0 123#R9",
      "(1.000000) can0 123#RR",
      "(1.000000) can0 123#00 X",
      "(1.000000) can0 123#00 T extra",
  };
  for (const char* line : bad) {
    const Expected<CandumpRecord> r = ParseCandumpLine(line);
    ASSERT_FALSE(r.ok()) << line;
    EXPECT_EQ(r.error().code, Error::kInputInvalid) << line;
    EXPECT_FALSE(r.error().message.empty()) << line;
  }
}

TEST(CanIoCandump, WriterReaderRoundTrip) {
  std::stringstream log;
  CandumpLogWriter w(log, "vcan0");
  std::vector<CanFrame> frames = {
      Frame(0x000, false, false, {}),         Frame(0x7FF, false, false, {1, 2, 3, 4, 5, 6, 7, 8}),
      Frame(0x1FFFFFFF, true, false, {0xFF}), Frame(0x123, false, true, {}, 3),
      Frame(0x00ABCDEF, true, true, {}),
  };
  uint64_t t = 1700000000000000ull;
  for (size_t i = 0; i < frames.size(); ++i) {
    w.Write(frames[i], i % 2 ? Direction::kRx : Direction::kTx, t + i * 1111);
  }
  EXPECT_EQ(w.lines(), frames.size());
  log << "\n";  // blank lines are skipped
  const auto read = ReadCandumpLog(log);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const std::vector<CandumpRecord>& records = *read;
  ASSERT_EQ(records.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(records[i].frame, frames[i]);
    EXPECT_EQ(records[i].frame.dlc, frames[i].dlc);
    EXPECT_EQ(records[i].timestamp_us, t + i * 1111);
    EXPECT_EQ(records[i].iface, "vcan0");
    EXPECT_EQ(records[i].direction, i % 2 ? Direction::kRx : Direction::kTx);
  }
}

TEST(CanIoCandump, ReaderNamesTheBadLine) {
  std::stringstream log("(1.000000) can0 123#00\n(1.000000) can0 123#0\n");
  const auto read = ReadCandumpLog(log);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, Error::kInputInvalid);
  EXPECT_EQ(read.error().message.rfind("line 2: ", 0), 0u) << read.error().message;
}

TEST(CanIoCandump, WallClockWriterAndNoDirection) {
  std::stringstream log;
  CandumpLogWriter w(log, "can1", /*direction_markers=*/false);
  w.Write(Frame(0x100, false, false, {0x01}), Direction::kTx);
  const auto read = ReadCandumpLog(log);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const std::vector<CandumpRecord>& records = *read;
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].direction, Direction::kNone);
  EXPECT_GT(records[0].timestamp_us, 1600000000000000ull);  // a real wall-clock time
}

// A scripted transport for the decorator.
class FakeTransport : public CanTransport {
 public:
  Outcome Send(const CanFrame& f) override {
    if (broken) return Fail(Error::kCommunication, "fake: gone");
    sent.push_back(f);
    return Outcome::Ok();
  }
  Expected<std::optional<CanFrame>> Receive(std::chrono::microseconds) override {
    if (broken) return Fail(Error::kCommunication, "fake: gone");
    if (inbox.empty()) return std::optional<CanFrame>();
    CanFrame f = inbox.front();
    inbox.pop_front();
    return std::optional<CanFrame>(f);
  }
  std::string description() const override { return "fake"; }
  std::vector<CanFrame> sent;
  std::deque<CanFrame> inbox;
  bool broken = false;
};

TEST(CanIoCandump, LoggingTransportRecordsBothDirections) {
  auto fake = std::make_unique<FakeTransport>();
  FakeTransport* raw = fake.get();
  raw->inbox.push_back(Frame(0x581, false, false, {0x60, 0, 0x21, 1, 0, 0, 0, 0}));
  std::stringstream log;
  LoggingTransport t(std::move(fake), std::make_unique<CandumpLogWriter>(log, "slcan0"));
  ASSERT_TRUE(t.Send(Frame(0x601, false, false, {0x23, 0, 0x21, 1, 1, 2, 3, 4})).ok());
  auto got = t.Receive(std::chrono::microseconds(0));
  ASSERT_TRUE(got.ok() && *got);
  got = t.Receive(std::chrono::microseconds(0));
  ASSERT_TRUE(got.ok());
  EXPECT_FALSE(*got);  // nothing logged for a timeout
  EXPECT_EQ(raw->sent.size(), 1u);
  EXPECT_EQ(t.description(), "fake (logged)");
  // The wrapped transport's failures pass through, and nothing is logged for them.
  raw->broken = true;
  const Outcome sent = t.Send(Frame(0x602, false, false, {}));
  ASSERT_FALSE(sent.ok());
  EXPECT_EQ(sent.error().code, Error::kCommunication);
  EXPECT_EQ(sent.error().message, "fake: gone");
  EXPECT_FALSE(t.Receive(std::chrono::microseconds(0)).ok());
  const auto read = ReadCandumpLog(log);
  ASSERT_TRUE(read.ok()) << read.error().message;
  const std::vector<CandumpRecord>& records = *read;
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].direction, Direction::kTx);
  EXPECT_EQ(records[0].frame.id, 0x601u);
  EXPECT_EQ(records[1].direction, Direction::kRx);
  EXPECT_EQ(records[1].frame.id, 0x581u);
  EXPECT_EQ(records[1].iface, "slcan0");
}

TEST(CanIoCandump, OpenFileErrors) {
  const auto opened = CandumpLogWriter::OpenFile("/nonexistent-dir/x.log", "can0");
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().code, Error::kIoError);
  EXPECT_EQ(opened.error().message, "cannot write CAN log '/nonexistent-dir/x.log'");
  EXPECT_EQ(*LogInterfaceName("socketcan:vcan0"), "vcan0");
  EXPECT_EQ(*LogInterfaceName("slcan-tcp:localhost:5"), "slcan0");
  EXPECT_FALSE(LogInterfaceName("bogus").ok());
}

}  // namespace
}  // namespace volcomp::can_io
