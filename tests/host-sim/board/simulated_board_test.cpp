// The simulator's board follows the configuration in force: after the tick rate and bit rate are
// changed over the simulated bus (0x2000:3, 0x2000:2, 0x1010 "save", NMT reset node) it ticks at
// the new rate — counted at the step I/O, and the drive model sees exact, rule-abiding steps from
// the data path planned for that rate — and its CAN controller runs at the new bit rate, which
// takes it off a bus running at another one. With a flash directory it keeps its flash in files,
// and a directory it cannot use is a failure of Start().
#include "volcomp/sim/simulated_board.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sdo_frames.hpp"

namespace volcomp {
namespace {

using testing::IsDownloadDone;
using testing::SdoDownload;

constexpr uint8_t kNode = 0x10;

class SimConfigTest : public ::testing::Test {
 protected:
  SimConfigTest() : bus_(1000000), board_(bus_, Options()), pc_(bus_.Attach("pc")) {}

  static sim::SimulatedBoardOptions Options() {
    sim::SimulatedBoardOptions o;
    o.settings.node_id = kNode;  // tick 50 kHz, 1000 kbit/s: the factory defaults
    o.write_enable_input = true;
    return o;
  }
  void Run(uint64_t ns) { sim::AdvanceInEventOrder(bus_, board_, bus_.now() + ns); }
  // Frames the PC received since the last call.
  std::vector<CanFrame> Received() {
    std::vector<CanFrame> out;
    CanFrame f;
    while (pc_.Receive(&f)) out.push_back(f);
    return out;
  }
  bool Write(uint16_t index, uint8_t sub, uint32_t value, uint8_t bytes) {
    Received();
    pc_.Send(SdoDownload(kNode, index, sub, value, bytes));
    Run(2000000);
    for (const CanFrame& f : Received()) {
      if (IsDownloadDone(f, kNode, index, sub)) return true;
    }
    return false;
  }
  // Feeds axis 0 with `per_20us` input steps every 20 us for `ns`, then lets the output settle.
  void Step(uint32_t per_20us, uint64_t ns) {
    for (uint64_t t = 0; t < ns; t += 20000) {
      board_.step_io().add_steps(0, static_cast<int32_t>(per_20us));
      Run(20000);
    }
    Run(5000000);
  }

  sim::SimBus bus_;
  sim::SimulatedBoard board_;
  sim::Endpoint& pc_;
};

TEST_F(SimConfigTest, TickAndBitRateChangedOverCanAreInForceAfterAResetNode) {
  ASSERT_TRUE(board_.Start().ok());
  Run(5000000);
  EXPECT_EQ(board_.tick_period_ns(), 20000u);
  ASSERT_TRUE(Write(0x2000, 3, 25000, 4));
  ASSERT_TRUE(Write(0x2000, 2, 500, 2));
  ASSERT_TRUE(Write(0x1010, 1, testing::kSave, 4));
  Received();
  pc_.Send(testing::NmtResetNode(kNode));
  Run(5000000);

  // The tick: what the data path assumes, what the timer was set to, what the board runs at.
  const uint32_t tick_hz = board_.app().settings().board.tick_hz;
  EXPECT_EQ(tick_hz, 25000u);
  EXPECT_EQ(board_.tick_timer().rate_hz(), 25000u);
  EXPECT_EQ(board_.tick_period_ns(), 40000u);
  const uint64_t before = board_.step_io().ticks_applied();
  Run(10000000);
  EXPECT_EQ(board_.step_io().ticks_applied() - before, 250u);  // 10 ms at 25 kHz

  // 100 kHz of input steps for 20 ms: the drive gets every step and no timing rule is broken.
  const int64_t start = board_.step_io().drive(0).position();
  Step(2, 20000000);
  EXPECT_EQ(board_.step_io().drive(0).position() - start, 2000);
  EXPECT_EQ(board_.step_io().drive(0).violations(), 0u)
      << (board_.step_io().drive(0).violation_log().empty()
              ? ""
              : board_.step_io().drive(0).violation_log().front());

  // The bit rate: the board's controller runs at 500 kbit/s on a 1 Mbit/s bus: it is off the
  // bus. Nothing it sends arrives (not even its boot-up); its attempts end in error frames until
  // it is bus-off.
  EXPECT_EQ(board_.endpoint().bitrate(), 500000u);
  bool heard = false;
  for (const CanFrame& f : Received()) heard = heard || f.id == 0x700u + kNode;
  EXPECT_FALSE(heard);
  EXPECT_TRUE(board_.endpoint().bus_off());
  EXPECT_GE(bus_.stats().bitrate_errors, 32u);
  EXPECT_FALSE(Write(0x2000, 3, 50000, 4));  // and it hears nobody
}

// A fresh directory under the test's temporary directory.
std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("volcomp_sim_board_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

TEST(SimBoardFlash, FlashFilesAreCreatedAtStartAndKeepTheSettings) {
  const std::string dir = TempDir("files") + "/flash";  // created with its parent
  sim::SimBus bus(1000000);
  sim::SimulatedBoardOptions o;
  o.flash_dir = dir;
  sim::SimulatedBoard board(bus, o);
  EXPECT_FALSE(std::filesystem::exists(dir));  // nothing on disk before Start()
  const Outcome started = board.Start();
  ASSERT_TRUE(started.ok()) << started.error().message;
  EXPECT_EQ(std::filesystem::file_size(dir + "/tables.bin"), o.table_flash_bytes);
  EXPECT_EQ(std::filesystem::file_size(dir + "/settings.bin"), o.settings_flash_bytes);
  std::filesystem::remove_all(std::filesystem::path(dir).parent_path());
}

TEST(SimBoardFlash, AFlashDirectoryThatCannotBeCreatedFailsStart) {
  const std::string base = TempDir("blocked");
  std::filesystem::create_directories(base);
  std::ofstream(base + "/file") << "not a directory\n";
  sim::SimBus bus(1000000);
  sim::SimulatedBoardOptions o;
  o.flash_dir = base + "/file/flash";
  sim::SimulatedBoard board(bus, o);
  const Outcome started = board.Start();
  ASSERT_FALSE(started.ok());
  EXPECT_EQ(started.error().code, Error::kIoError);
  EXPECT_EQ(started.error().message.rfind(o.flash_dir + ": cannot create: ", 0), 0u)
      << started.error().message;
  std::filesystem::remove_all(base);
}

}  // namespace
}  // namespace volcomp
