// SocketCAN: error paths on a machine without AF_CAN, error-frame decoding, the CanPort backend's
// failure reporting. (The real socket path runs in the user-mode-linux test.)
#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include "volcomp/can_io/socketcan_transport.hpp"
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

std::string OpenError(const std::string& spec) {
  try {
    can_io::OpenTransport(spec);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
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
  EXPECT_NE(s.Open("an-interface-name-too-long", {}).find("bad interface name"), std::string::npos);
  EXPECT_FALSE(s.is_open());
}

TEST(CanIoSocketCan, PortReportsOpenFailure) {
  SocketCanPort port;
  EXPECT_EQ(port.Open("vcnoexist9").error(), Error::kIoError);
  EXPECT_FALSE(port.is_open());
  EXPECT_FALSE(port.last_error().empty());
  CanFrame f;
  f.id = 0x123;
  EXPECT_EQ(port.Send(f).error(), Error::kNotReady);
  EXPECT_FALSE(port.Receive(&f));
  port.Service();  // harmless when closed
}

TEST(CanIoSocketCan, RestartOfMissingInterfaceFails) {
  const std::string e = RequestCanRestart("vcnoexist9");
  EXPECT_NE(e.find("no such interface"), std::string::npos) << e;
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
