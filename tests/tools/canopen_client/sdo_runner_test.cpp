// The blocking SDO helpers honour the caller's options (the PC tool's --timeout-ms).
#include "volcomp/canopen_client/sdo_runner.hpp"

#include <gtest/gtest.h>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp::canopen_client {
namespace {

// A node that never answers, on a virtual clock that receive() advances by its full timeout.
struct SilentLink {
  uint64_t now_us = 1000;
  int sent = 0;
  FrameLink link() {
    FrameLink l;
    l.send = [this](const CanFrame&) {
      ++sent;
      return Outcome::Ok();
    };
    l.receive = [this](uint64_t timeout_us) -> Expected<std::optional<CanFrame>> {
      now_us += timeout_us;
      return std::optional<CanFrame>();
    };
    l.now_us = [this] { return now_us; };
    return l;
  }
};

constexpr uint32_t kAbortTimeout = 0x05040000;

TEST(SdoRunner, ReadU32TimesOutAfterTheGivenTimeout) {
  SilentLink s;
  SdoClient::Options o;
  o.timeout_ms = 50;
  const SdoExpected<uint32_t> r = ReadU32(s.link(), 0x10, 0x2104, 0, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(canopen::Code(r.error().abort), kAbortTimeout);
  EXPECT_EQ(r.error().code, Error::kCommunication);
  const uint64_t waited_us = s.now_us - 1000;
  EXPECT_GE(waited_us, 50000u);
  EXPECT_LT(waited_us, 70000u);  // not the 1000 ms default
  EXPECT_EQ(s.sent, 2);          // the request and the abort
}

TEST(SdoRunner, WriteU32TimesOutAfterTheGivenTimeout) {
  SilentLink s;
  SdoClient::Options o;
  o.timeout_ms = 20;
  const canopen::ObjectEntry& control = canopen::Entry(canopen::ObjectId::kTableControl);
  const SdoOutcome r = WriteU32(s.link(), 0x10, control.index, control.sub,
                                canopen::Value(canopen::TableCommand::kVerify), 1, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(canopen::Code(r.error().abort), kAbortTimeout);
  EXPECT_EQ(r.error().code, Error::kCommunication);
  const uint64_t waited_us = s.now_us - 1000;
  EXPECT_GE(waited_us, 20000u);
  EXPECT_LT(waited_us, 40000u);
}

// What the link knows (frames the kernel dropped) is added to a failure's message, and only to a
// failure's.
TEST(SdoRunner, TheLinksDiagnosisEndsAFailuresMessage) {
  SilentLink s;
  FrameLink link = s.link();
  int asked = 0;
  link.diagnose = [&asked] {
    ++asked;
    return std::string("12 received frames were lost");
  };
  SdoClient::Options o;
  o.timeout_ms = 20;
  const SdoExpected<uint32_t> r = ReadU32(link, 0x10, 0x2104, 0, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(asked, 1);
  const std::string& m = r.error().message;
  EXPECT_NE(m.find("timed out); 12 received frames were lost"), std::string::npos) << m;
  // A transfer that succeeds does not ask.
  FrameLink answering = link;
  answering.receive = [&s](uint64_t) -> Expected<std::optional<CanFrame>> {
    CanFrame f;
    f.id = 0x590;
    f.dlc = 8;
    const uint8_t reply[8] = {0x4B, 0x04, 0x21, 0x00, 0x34, 0x12, 0, 0};
    for (int i = 0; i < 8; ++i) f.data[i] = reply[i];
    s.now_us += 100;
    return std::optional<CanFrame>(f);
  };
  const SdoExpected<uint32_t> ok = ReadU32(answering, 0x10, 0x2104, 0, o);
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  EXPECT_EQ(*ok, 0x1234u);
  EXPECT_EQ(asked, 1);
}

TEST(SdoRunner, DefaultTimeoutIsOneSecond) {
  SilentLink s;
  EXPECT_FALSE(ReadU32(s.link(), 0x10, 0x2104, 0).ok());
  EXPECT_GE(s.now_us - 1000, 1000000u);
  EXPECT_LT(s.now_us - 1000, 1020000u);
}

}  // namespace
}  // namespace volcomp::canopen_client
