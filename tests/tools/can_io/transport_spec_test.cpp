// Transport specs: parsing and the errors for bad specs and unreachable endpoints.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "volcomp/can_io/transport.hpp"

namespace volcomp::can_io {
namespace {

// The failure's message ("" for a success); `code` receives its code.
template <typename T>
std::string ErrorOf(const Expected<T>& r, Error* code = nullptr) {
  if (r.ok()) return "";
  if (code != nullptr) *code = r.error().code;
  return r.error().message;
}

bool Contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TransportSpec Parsed(const std::string& spec) {
  const Expected<TransportSpec> s = ParseTransportSpec(spec);
  EXPECT_TRUE(s.ok()) << s.error().message;
  return s.ok() ? *s : TransportSpec();
}

TEST(CanIoTransportSpec, ParsesTheThreeForms) {
  TransportSpec s = Parsed("socketcan:vcan0");
  EXPECT_EQ(s.kind, TransportSpec::Kind::kSocketCan);
  EXPECT_EQ(s.target, "vcan0");

  s = Parsed("slcan:/dev/pts/3");
  EXPECT_EQ(s.kind, TransportSpec::Kind::kSlcanSerial);
  EXPECT_EQ(s.target, "/dev/pts/3");
  EXPECT_EQ(s.bitrate, 0u);

  s = Parsed("slcan:/dev/ttyACM0@500k");
  EXPECT_EQ(s.target, "/dev/ttyACM0");
  EXPECT_EQ(s.bitrate, 500000u);

  s = Parsed("slcan-tcp:127.0.0.1:29536");
  EXPECT_EQ(s.kind, TransportSpec::Kind::kSlcanTcp);
  EXPECT_EQ(s.target, "127.0.0.1");
  EXPECT_EQ(s.port, 29536);

  s = Parsed("slcan-tcp:[::1]:80@1M");
  EXPECT_EQ(s.target, "::1");
  EXPECT_EQ(s.port, 80);
  EXPECT_EQ(s.bitrate, 1000000u);

  s = Parsed("slcan-tcp:localhost:1@83333");
  EXPECT_EQ(s.bitrate, 83333u);
}

TEST(CanIoTransportSpec, Bitrates) {
  EXPECT_EQ(*ParseBitrate("10k"), 10000u);
  EXPECT_EQ(*ParseBitrate("125K"), 125000u);
  EXPECT_EQ(*ParseBitrate("800000"), 800000u);
  EXPECT_EQ(*ParseBitrate("1M"), 1000000u);
  for (const char* bad : {"", "k", "750000", "750k", "1m", "1MM", "-1", "1e6", "99999999999999"}) {
    const Expected<uint32_t> r = ParseBitrate(bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_EQ(r.error().code, Error::kInvalidArgument) << bad;
    EXPECT_NE(r.error().message.find("is not one of 10k"), std::string::npos) << bad;
  }
}

TEST(CanIoTransportSpec, BadSpecsExplainTheForms) {
  const char* bad[] = {"",
                       "can0",
                       "socketcan:",
                       "socketcan:can0@500k",
                       "slcan:",
                       "slcan:@1M",
                       "slcan:/dev/ttyUSB0@750000",
                       "slcan-tcp:host",
                       "slcan-tcp::123",
                       "slcan-tcp:h:0",
                       "slcan-tcp:h:65536",
                       "slcan-tcp:h:12a",
                       "slcan-tcp:h:+5",
                       "slcan-tcp:h:",
                       "serial:/dev/ttyS0"};
  for (const char* spec : bad) {
    Error code = Error::kOk;
    const std::string e = ErrorOf(ParseTransportSpec(spec), &code);
    EXPECT_EQ(code, Error::kInvalidArgument) << spec;
    EXPECT_TRUE(Contains(e, "expected socketcan:IFACE")) << spec << " -> " << e;
    EXPECT_EQ(ErrorOf(OpenTransport(spec)), e);
  }
}

TEST(CanIoTransportSpec, UnreachableEndpoints) {
  // A port that was free a moment ago: connection refused.
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(fd);
  const std::string spec = "slcan-tcp:127.0.0.1:" + std::to_string(ntohs(a.sin_port));
  Error code = Error::kOk;
  std::string e = ErrorOf(OpenTransport(spec), &code);
  EXPECT_EQ(code, Error::kCommunication);
  EXPECT_TRUE(Contains(e, "cannot connect")) << e;
  EXPECT_TRUE(Contains(e, spec)) << e;

  code = Error::kOk;
  e = ErrorOf(OpenTransport("slcan:/nonexistent/ttyX"), &code);
  EXPECT_EQ(code, Error::kCommunication);
  EXPECT_TRUE(Contains(e, "cannot open")) << e;
  e = ErrorOf(OpenTransport("slcan:/dev/null"));
  EXPECT_TRUE(Contains(e, "not a serial device or pty")) << e;
}

}  // namespace
}  // namespace volcomp::can_io
