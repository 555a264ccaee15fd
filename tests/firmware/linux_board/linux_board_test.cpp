// volcomp-fw-linux's board in process (LinuxBoard: file flash, fake GPIO state file, the timerfd
// tick; mock CAN ports instead of SocketCAN): the tick rate and bit rate changed over CAN
// (0x2000:3, 0x2000:2, 0x1010 "save", NMT reset node) are in force afterwards: the timerfd is
// re-armed with the period of the rate the data path now assumes, and the controller port got the
// bit rate.
#include "volcomp/linux_board/linux_board.hpp"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "file_contents.hpp"
#include "sdo_frames.hpp"
#include "temp_paths.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/linux_board/config_file.hpp"

namespace volcomp::linux_board {
namespace {

using volcomp::testing::IsDownloadDone;
using volcomp::testing::SdoDownload;

constexpr uint8_t kNode = 0x10;

class LinuxBoardConfigTest : public ::testing::Test {
 protected:
  LinuxBoardConfigTest() : controller_(&clock_, nullptr, 256) {
    volcomp::testing::WriteText(dir_ / "gpio", "write_enable=1\n");
    const std::string text =
        "[board]\nnode_id = 16\ntick_hz = 1000\naxes = X\n"
        "[axis X]\nunits_per_step = 0.001\n"
        "[can]\ncontroller = test0\n"
        "[gpio]\nbackend = fake:" +
        dir_.path() +
        "/gpio\n"
        "[flash]\ntables = " +
        dir_.path() + "/tables.bin\nsettings = " + dir_.path() +
        "/settings.bin\ntable_bank_kib = 16\nsync = false\n";
    const auto parsed = ParseConfig(text, "test.conf");
    EXPECT_TRUE(parsed.ok()) << parsed.error().ToString();
    if (parsed.ok()) config_ = *parsed;
  }

  LinuxBoard::Options Options() {
    LinuxBoard::Options o;
    o.log = [this](const std::string& line) { log_.push_back(line); };
    return o;
  }
  // One pass of the event loop: frames to the node, then the tick when the timerfd fires.
  void Pass(LinuxBoard& board) {
    board.app().PumpFrames();
    pollfd p{board.tick_timer().fd(), POLLIN, 0};
    ::poll(&p, 1, 20);
    board.OnTimer();
  }
  bool Write(LinuxBoard& board, uint16_t index, uint8_t sub, uint32_t value, uint8_t bytes) {
    controller_.TakeSent();
    controller_.Inject(SdoDownload(kNode, index, sub, value, bytes));
    for (int i = 0; i < 5; ++i) {
      Pass(board);
      for (const CanFrame& f : controller_.TakeSent()) {
        if (IsDownloadDone(f, kNode, index, sub)) return true;
      }
    }
    return false;
  }

  volcomp::testing::ScratchDir dir_{"linux_board"};
  LinuxBoardConfig config_;
  hal::mock::MockClock clock_;
  hal::mock::MockCan controller_;
  std::vector<std::string> log_;
};

TEST_F(LinuxBoardConfigTest, TickAndBitRateChangedOverCanAreInForceAfterAResetNode) {
  LinuxBoard board(config_, Options());
  const Expected<void> opened = board.Open(&controller_, nullptr);
  ASSERT_TRUE(opened.ok()) << opened.error().message;
  EXPECT_EQ(board.tick_timer().period_ns(), 1000000u);
  EXPECT_TRUE(board.tick_timer().running());
  EXPECT_EQ(controller_.bitrate_bps(), 1000000u);

  ASSERT_TRUE(Write(board, 0x2000, 3, 2000, 4));
  ASSERT_TRUE(Write(board, 0x2000, 2, 500, 2));
  ASSERT_TRUE(Write(board, 0x1010, 1, volcomp::testing::kSave, 4));
  const int fd = board.tick_timer().fd();
  controller_.Inject(volcomp::testing::NmtResetNode(kNode));
  for (int i = 0; i < 3; ++i) Pass(board);

  // The rate the data path assumes and the period the kernel's timer runs with agree.
  const uint32_t tick_hz = board.app().app().settings().board.tick_hz;
  EXPECT_EQ(tick_hz, 2000u);
  EXPECT_EQ(board.tick_timer().rate_hz(), 2000u);
  EXPECT_TRUE(board.tick_timer().running());
  EXPECT_EQ(board.tick_timer().fd(), fd);  // the event loop's fd stays valid
  itimerspec spec{};
  ASSERT_EQ(timerfd_gettime(board.tick_timer().fd(), &spec), 0);
  EXPECT_EQ(spec.it_interval.tv_sec, 0);
  EXPECT_EQ(uint64_t(spec.it_interval.tv_nsec), 1000000000u / tick_hz);
  // The controller port got the bit rate in force.
  EXPECT_EQ(controller_.bitrate_bps(), 500000u);
  // The reset is logged with what is in force.
  ASSERT_FALSE(log_.empty());
  EXPECT_NE(log_.back().find("node reset: tick 2000 Hz (timer period 500000 ns), bit rate 500 "
                             "kbit/s"),
            std::string::npos)
      << log_.back();

  // A restart of the process runs the stored settings from the first tick.
  board.Shutdown();
}

TEST_F(LinuxBoardConfigTest, StoredSettingsAreInForceFromTheStart) {
  {
    LinuxBoard board(config_, Options());
    ASSERT_TRUE(board.Open(&controller_, nullptr).ok());
    ASSERT_TRUE(Write(board, 0x2000, 3, 4000, 4));
    ASSERT_TRUE(Write(board, 0x1010, 1, volcomp::testing::kSave, 4));
    board.Shutdown();
  }
  LinuxBoard board(config_, Options());
  ASSERT_TRUE(board.Open(&controller_, nullptr).ok());
  EXPECT_EQ(board.app().app().settings().board.tick_hz, 4000u);
  EXPECT_EQ(board.tick_timer().period_ns(), 250000u);
  itimerspec spec{};
  ASSERT_EQ(timerfd_gettime(board.tick_timer().fd(), &spec), 0);
  EXPECT_EQ(spec.it_interval.tv_nsec, 250000);
}

TEST_F(LinuxBoardConfigTest, ABitRateMismatchIsLoggedAndKeepsTheBoardRunning) {
  controller_.RefuseBitrate(Error::kCanBitrateMismatch);
  LinuxBoard board(config_, Options());
  ASSERT_TRUE(board.Open(&controller_, nullptr).ok());
  EXPECT_EQ(board.app().app().config_status().error(), Error::kCanBitrateMismatch);
  EXPECT_TRUE(board.tick_timer().running());
  EXPECT_NE(board.DescribeConfigInForce().find("another bit rate"), std::string::npos)
      << board.DescribeConfigInForce();
  const std::string text = volcomp::testing::ReadText(dir_ / "gpio.out");
  EXPECT_NE(text.find("fault=1"), std::string::npos) << text;
}

}  // namespace
}  // namespace volcomp::linux_board
