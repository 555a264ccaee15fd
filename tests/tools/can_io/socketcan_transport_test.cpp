// SocketCAN: error paths on a machine without AF_CAN, error-frame decoding, the CanPort backend's
// failure reporting, the interface bit rate from rtnetlink. (The real socket path runs in the
// user-mode-linux test.)
#include "volcomp/can_io/socketcan_transport.hpp"

#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/netlink.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "volcomp/can_io/transport.hpp"
#include "volcomp/hal/linux/socketcan_port.hpp"
#include "volcomp/hal/linux/socketcan_socket.hpp"

namespace volcomp::hal::socketcan {
namespace {

bool KernelHasCan() {
  const int fd = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd >= 0) ::close(fd);
  return fd >= 0 || errno != EAFNOSUPPORT;
}

// The message of opening `spec` (kCommunication: no adapter), "" when it opened.
std::string OpenError(const std::string& spec) {
  const auto opened = can_io::OpenTransport(spec);
  if (opened.ok()) return "";
  EXPECT_EQ(opened.error().code, Error::kCommunication) << opened.error().message;
  return opened.error().message;
}

TEST(CanIoSocketCan, OpenWithoutKernelSupportGivesTheClearError) {
  if (KernelHasCan()) GTEST_SKIP() << "this kernel has AF_CAN (the UML test covers it)";
  const std::string e = OpenError("socketcan:vcan0");
  EXPECT_NE(e.find("address family not supported: this kernel has no CAN support"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("slcan-tcp:"), std::string::npos) << e;
  EXPECT_NE(e.find("user-mode-linux"), std::string::npos) << e;
}

TEST(CanIoSocketCan, MissingInterfaceIsNamed) {
  const std::string e = OpenError("socketcan:vcnoexist9");
  EXPECT_TRUE(e.find("no CAN support") != std::string::npos ||
              e.find("no such interface") != std::string::npos)
      << e;
  SocketCanSocket s;
  const Expected<void> opened = s.Open("an-interface-name-too-long", {});
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().code, Error::kInvalidArgument);
  EXPECT_NE(opened.error().message.find("bad interface name"), std::string::npos);
  EXPECT_FALSE(s.is_open());
}

TEST(CanIoSocketCan, PortReportsOpenFailure) {
  SocketCanPort port;
  const Expected<void> opened = port.Open("vcnoexist9");
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().code, Error::kIoError);
  EXPECT_FALSE(port.is_open());
  EXPECT_FALSE(opened.error().message.empty());
  CanFrame f;
  f.id = 0x123;
  EXPECT_EQ(port.Send(f).error(), Error::kNotReady);
  EXPECT_EQ(port.SetBitrate(500000).error(), Error::kNotReady);
  EXPECT_EQ(port.bitrate_check().configured_bps, 500000u);
  EXPECT_FALSE(port.Receive(&f));
  port.Service();  // harmless when closed
}

TEST(CanIoSocketCan, RestartOfMissingInterfaceFails) {
  const Expected<void> r = RequestCanRestart("vcnoexist9");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("no such interface"), std::string::npos) << r.error().message;
}

// An RTM_NEWLINK answer as the kernel lays it out (linux/rtnetlink.h, linux/if_link.h,
// linux/can/netlink.h): ifinfomsg, then IFLA_IFNAME and IFLA_LINKINFO { IFLA_INFO_KIND,
// IFLA_INFO_DATA { IFLA_CAN_BITTIMING, IFLA_CAN_STATE } } when `kind` is "can".
std::vector<uint8_t> LinkAnswer(const std::string& kind, uint32_t bitrate) {
  std::vector<uint8_t> m(NLMSG_LENGTH(sizeof(ifinfomsg)), 0);
  auto put = [&m](size_t at, const void* p, size_t n) { std::memcpy(m.data() + at, p, n); };
  auto attr = [&](uint16_t type, const void* data, size_t n) {
    const size_t at = m.size();
    rtattr a{};
    a.rta_type = type;
    a.rta_len = static_cast<uint16_t>(RTA_LENGTH(n));
    m.resize(at + RTA_SPACE(n), 0);
    put(at, &a, sizeof a);
    if (n != 0) put(at + RTA_LENGTH(0), data, n);
    return at;
  };
  auto close = [&](size_t at) {
    const auto len = static_cast<uint16_t>(m.size() - at);
    put(at, &len, sizeof len);  // rta_len is the first field
  };
  attr(IFLA_IFNAME, "can0", 5);
  const size_t info = attr(IFLA_LINKINFO, nullptr, 0);
  attr(IFLA_INFO_KIND, kind.c_str(), kind.size());
  if (kind == "can") {
    const size_t data = attr(IFLA_INFO_DATA, nullptr, 0);
    can_bittiming bt{};
    bt.bitrate = bitrate;
    bt.sample_point = 875;
    attr(IFLA_CAN_BITTIMING, &bt, sizeof bt);
    const uint32_t state = CAN_STATE_ERROR_ACTIVE;
    attr(IFLA_CAN_STATE, &state, sizeof state);
    close(data);
  }
  close(info);
  nlmsghdr h{};
  h.nlmsg_len = static_cast<uint32_t>(m.size());
  h.nlmsg_type = RTM_NEWLINK;
  put(0, &h, sizeof h);
  return m;
}

TEST(CanIoSocketCan, InterfaceBitrateFromTheKernelsAnswer) {
  std::vector<uint8_t> m = LinkAnswer("can", 500000);
  Expected<uint32_t> r = ParseLinkBitrate(m.data(), m.size());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(*r, 500000u);
  m = LinkAnswer("can", 0);  // a CAN interface whose bit rate was never set
  EXPECT_EQ(ParseLinkBitrate(m.data(), m.size()).error().code, Error::kNotFound);
  m = LinkAnswer("vcan", 0);  // virtual: no bit timing at all
  r = ParseLinkBitrate(m.data(), m.size());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kNotFound);
  EXPECT_NE(r.error().message.find("vcan"), std::string::npos) << r.error().message;
  // A netlink error answer.
  std::vector<uint8_t> e(NLMSG_LENGTH(sizeof(nlmsgerr)), 0);
  nlmsghdr h{};
  h.nlmsg_len = static_cast<uint32_t>(e.size());
  h.nlmsg_type = NLMSG_ERROR;
  std::memcpy(e.data(), &h, sizeof h);
  const int err = -ENODEV;
  std::memcpy(e.data() + NLMSG_LENGTH(0), &err, sizeof err);
  EXPECT_EQ(ParseLinkBitrate(e.data(), e.size()).error().code, Error::kIoError);
}

TEST(CanIoSocketCan, InterfacesWithoutBitTimingHaveNoRate) {
  EXPECT_EQ(ReadCanBitrate("vcnoexist9").error().code, Error::kNotFound);
  const Expected<uint32_t> lo = ReadCanBitrate("lo");  // the kernel answers; no CAN data
  ASSERT_FALSE(lo.ok());
  EXPECT_EQ(lo.error().code, Error::kNotFound) << lo.error().message;
}

TEST(CanIoSocketCan, DecodesErrorFrames) {
  uint8_t data[8] = {};
  CanErrorInfo i = DecodeErrorFrame(CAN_ERR_FLAG | CAN_ERR_BUSOFF, data);
  EXPECT_TRUE(i.bus_off);
  EXPECT_TRUE(i.state_changed);
  EXPECT_EQ(i.state, BusState::kBusOff);
  EXPECT_EQ(DescribeError(i), "bus-off");

  data[1] = CAN_ERR_CRTL_TX_PASSIVE;
  i = DecodeErrorFrame(CAN_ERR_FLAG | CAN_ERR_CRTL, data);
  EXPECT_EQ(i.state, BusState::kErrorPassive);
  data[1] = CAN_ERR_CRTL_RX_WARNING;
  i = DecodeErrorFrame(CAN_ERR_CRTL, data);
  EXPECT_EQ(i.state, BusState::kErrorWarning);
  data[1] = CAN_ERR_CRTL_ACTIVE;
  i = DecodeErrorFrame(CAN_ERR_CRTL, data);
  EXPECT_EQ(i.state, BusState::kErrorActive);
  EXPECT_TRUE(i.state_changed);
  data[1] = CAN_ERR_CRTL_RX_OVERFLOW;
  i = DecodeErrorFrame(CAN_ERR_CRTL, data);
  EXPECT_TRUE(i.rx_overflow);
  EXPECT_FALSE(i.state_changed);

  data[1] = 0;
  data[6] = 200;
  data[7] = 3;
  i = DecodeErrorFrame(CAN_ERR_FLAG | CAN_ERR_ACK | CAN_ERR_CNT | CAN_ERR_PROT, data);
  EXPECT_TRUE(i.no_ack);
  EXPECT_TRUE(i.protocol_error);
  EXPECT_TRUE(i.has_counters);
  EXPECT_EQ(i.tx_errors, 200);
  EXPECT_EQ(i.rx_errors, 3);
  EXPECT_FALSE(i.state_changed);
  EXPECT_EQ(DescribeError(i), "no ack, protocol violation, tx errors 200 rx errors 3");

  i = DecodeErrorFrame(CAN_ERR_RESTARTED, data);
  EXPECT_TRUE(i.restarted);
  EXPECT_EQ(i.state, BusState::kErrorActive);
  i = DecodeErrorFrame(CAN_ERR_TRX, data);
  EXPECT_EQ(DescribeError(i), "error frame (class 0x010)");
}

TEST(CanIoSocketCan, ErrorTexts) {
  EXPECT_NE(SocketCanErrorText("x", ENETDOWN).find("ip link set"), std::string::npos);
  EXPECT_NE(SocketCanErrorText("x", EPERM).find("CAP_NET_ADMIN"), std::string::npos);
  EXPECT_STREQ(BusStateName(BusState::kErrorPassive), "error-passive");
}

}  // namespace
}  // namespace volcomp::hal::socketcan
