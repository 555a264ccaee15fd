// The Linux board's temperature files (temperature_files.hpp, docs/linux-board.md [sensors]): the
// formats the kernel's drivers write (hwmon temp*_input and w1 temperature in millidegrees C,
// w1_slave's two lines with the CRC verdict), failures as "no reading" named once in the log, the
// [sensors] keys, and a channel of LinuxBoard fed by a file through the board's thermal path.
#include "volcomp/linux_board/temperature_files.hpp"

#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "file_contents.hpp"
#include "temp_paths.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/linux_board/config_file.hpp"
#include "volcomp/linux_board/linux_board.hpp"

namespace volcomp::linux_board {
namespace {

using thermal::ChannelSource;
using thermal::ChannelState;
using thermal::kNoReading_cC;

int16_t Parsed(const std::string& text) {
  const Expected<int16_t> v = ParseTemperatureText(text);
  EXPECT_TRUE(v.ok()) << text;
  return v.ok() ? *v : kNoReading_cC;
}

TEST(TemperatureText, MillidegreesRoundToCentidegrees) {
  EXPECT_EQ(Parsed("23125\n"), 2313);  // 23.125 C: half away from zero
  EXPECT_EQ(Parsed("23124"), 2312);
  EXPECT_EQ(Parsed("0\n"), 0);
  EXPECT_EQ(Parsed("-1250\n"), -125);
  EXPECT_EQ(Parsed("-1255"), -126);
  EXPECT_EQ(Parsed("-55000"), -5500);    // DS18B20's lowest
  EXPECT_EQ(Parsed("327670"), 32767);    // the top of int16 cC
  EXPECT_EQ(Parsed("-327670"), -32767);  // never 0x8000 ("no reading")
}

TEST(TemperatureText, W1SlaveNeedsItsCrcVerdict) {
  EXPECT_EQ(Parsed("72 01 4b 46 7f ff 0e 10 57 : crc=57 YES\n72 01 4b 46 7f ff 0e 10 57 t=23125\n"),
            2313);
  EXPECT_EQ(
      Parsed("5e ff 4b 46 7f ff 02 10 56 : crc=56 YES\n5e ff 4b 46 7f ff 02 10 56 t=-10125\n"),
      -1013);
  const Expected<int16_t> bad = ParseTemperatureText(
      "72 01 4b 46 7f ff 0e 10 57 : crc=00 NO\n72 01 4b 46 7f ff 0e 10 57 t=0\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("CRC"), std::string::npos);
  EXPECT_FALSE(ParseTemperatureText("t=23125\n").ok());  // no verdict line
}

TEST(TemperatureText, AnythingElseIsNoTemperature) {
  for (const char* text : {"", "\n", "abc", "23.5", "0x10", "23125 24000", "--5", "-", "1234567890",
                           "327675", "-327675"}) {
    const Expected<int16_t> v = ParseTemperatureText(text);
    EXPECT_FALSE(v.ok()) << "'" << text << "'";
  }
  const Expected<int16_t> far = ParseTemperatureText("400000\n");
  ASSERT_FALSE(far.ok());
  EXPECT_NE(far.error().message.find("400000"), std::string::npos) << far.error().message;
}

class TemperatureFilesTest : public ::testing::Test {
 protected:
  std::array<std::string, thermal::kMaxChannels> Paths() {
    std::array<std::string, thermal::kMaxChannels> p;
    p[0] = dir_.path() + "/temp1_input";
    p[2] = dir_.path() + "/w1_slave";
    return p;
  }
  volcomp::testing::ScratchDir dir_{"temperature_files"};
};

TEST_F(TemperatureFilesTest, ReadingsFailuresAndRecoveriesEachOnce) {
  TemperatureFiles files(Paths(), 500);
  hal::TemperatureInputs& in = files;
  int16_t v = 0;
  volcomp::testing::WriteText(dir_.path() + "/temp1_input", "21500\n");
  files.ReadOnce(0);
  ASSERT_TRUE(in.Take(0, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, 2150);
  EXPECT_FALSE(in.Take(0, ChannelSource::kLinuxFile, &v));  // once per read
  files.ReadOnce(0);
  EXPECT_FALSE(in.Take(0, ChannelSource::kBoardNtc, &v));   // no ADC on this board
  EXPECT_FALSE(in.Take(1, ChannelSource::kLinuxFile, &v));  // no file for channel 2
  EXPECT_TRUE(files.TakeLog().empty());

  // The file disappears (a sensor unplugged, its hwmon device gone): no reading, named once.
  ASSERT_EQ(std::remove((dir_.path() + "/temp1_input").c_str()), 0);
  files.ReadOnce(0);
  ASSERT_TRUE(in.Take(0, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, kNoReading_cC);
  std::vector<std::string> log = files.TakeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("temperature_file.1"), std::string::npos) << log[0];
  EXPECT_NE(log[0].find("temp1_input"), std::string::npos) << log[0];
  EXPECT_NE(log[0].find("No such file"), std::string::npos) << log[0];
  files.ReadOnce(0);
  ASSERT_TRUE(in.Take(0, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, kNoReading_cC);
  EXPECT_TRUE(files.TakeLog().empty());  // still failing: not logged again

  // Garbage, then a negative temperature: the failure changes (logged), then ends (logged).
  volcomp::testing::WriteText(dir_.path() + "/temp1_input", "garbage\n");
  files.ReadOnce(0);
  ASSERT_TRUE(in.Take(0, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, kNoReading_cC);
  log = files.TakeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("'garbage'"), std::string::npos) << log[0];
  volcomp::testing::WriteText(dir_.path() + "/temp1_input", "-7375\n");
  files.ReadOnce(0);
  ASSERT_TRUE(in.Take(0, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, -738);
  log = files.TakeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("reading again"), std::string::npos) << log[0];
}

TEST_F(TemperatureFilesTest, AReadErrorIsNoReading) {
  // A read() that fails (here EISDIR: the path is a folder; EIO from a sensor's bus takes the
  // same path).
  std::array<std::string, thermal::kMaxChannels> p;
  p[4] = dir_.path();
  TemperatureFiles files(p, 500);
  files.ReadOnce(4);
  int16_t v = 0;
  ASSERT_TRUE(static_cast<hal::TemperatureInputs&>(files).Take(4, ChannelSource::kLinuxFile, &v));
  EXPECT_EQ(v, kNoReading_cC);
  const std::vector<std::string> log = files.TakeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("temperature_file.5"), std::string::npos) << log[0];
  EXPECT_NE(log[0].find("read: "), std::string::npos) << log[0];
}

TEST_F(TemperatureFilesTest, ReaderThreadsPublishAndStop) {
  volcomp::testing::WriteText(dir_.path() + "/temp1_input", "30000\n");
  volcomp::testing::WriteText(dir_.path() + "/w1_slave",
                              "aa 01 4b 46 7f ff 06 10 8f : crc=8f YES\naa 01 4b 46 7f ff 06 10 "
                              "8f t=26625\n");
  TemperatureFiles files(Paths(), 100);
  files.Start();
  hal::TemperatureInputs& in = files;
  int16_t v0 = 0, v2 = 0;
  bool got0 = false, got2 = false;
  for (int i = 0; i < 300 && !(got0 && got2); ++i) {  // up to 3 s on a loaded machine
    got0 = got0 || in.Take(0, ChannelSource::kLinuxFile, &v0);
    got2 = got2 || in.Take(2, ChannelSource::kLinuxFile, &v2);
    ::usleep(10000);
  }
  files.Stop();
  ASSERT_TRUE(got0 && got2);
  EXPECT_EQ(v0, 3000);
  EXPECT_EQ(v2, 2663);
}

TEST(SensorsConfig, KeysReadCheckedAndWrittenBack) {
  const std::string base =
      "[board]\naxes = X\n[axis X]\nunits_per_step = 0.001\n[can]\ncontroller = can0\n"
      "[flash]\ntables = /tmp/t.bin\n";
  const auto ok = ParseConfig(base +
                                  "[sensors]\ntemperature_file.1 = /sys/class/hwmon/hwmon2/"
                                  "temp1_input\ntemperature_file.8 = /sys/bus/w1/devices/"
                                  "28-0316a2794aff/w1_slave\ntemperature_period_ms = 250\n",
                              "a.conf");
  ASSERT_TRUE(ok.ok()) << ok.error().ToString();
  EXPECT_EQ(ok->temperature_files[0], "/sys/class/hwmon/hwmon2/temp1_input");
  EXPECT_EQ(ok->temperature_files[7], "/sys/bus/w1/devices/28-0316a2794aff/w1_slave");
  EXPECT_TRUE(ok->temperature_files[1].empty());
  EXPECT_EQ(ok->temperature_period_ms, 250u);
  const std::string text = FormatConfig(*ok);
  EXPECT_NE(text.find("temperature_file.8 = /sys/bus/w1/devices/28-0316a2794aff/w1_slave"),
            std::string::npos)
      << text;
  const auto again = ParseConfig(text, "formatted");
  ASSERT_TRUE(again.ok()) << again.error().ToString();
  EXPECT_EQ(again->temperature_files, ok->temperature_files);

  const auto defaults = ParseConfig(base, "b.conf");
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(defaults->temperature_period_ms, 500u);

  for (const char* bad : {"temperature_file.9 = /x\n", "temperature_file.1 = hwmon/temp1\n",
                          "temperature_period_ms = 50\n"}) {
    const auto r = ParseConfig(base + "[sensors]\n" + bad, "c.conf");
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.error().ToString().find("c.conf"), std::string::npos) << r.error().ToString();
  }
}

// A channel whose source is a Linux file: valid from its file through the board's thermal period,
// out of range when the file goes (named once in the log); a channel whose source is a Linux file
// without one is named at start.
TEST(LinuxBoardTemperature, AFileFeedsItsChannel) {
  volcomp::testing::ScratchDir dir("linux_board_temperature");
  volcomp::testing::WriteText(dir.path() + "/temp", "24500\n");
  const std::string text =
      "[board]\nnode_id = 16\ntick_hz = 1000\naxes = X\n"
      "[axis X]\nunits_per_step = 0.001\n[can]\ncontroller = test0\n"
      "[flash]\ntables = " +
      dir.path() + "/tables.bin\ntable_bank_kib = 16\nsync = false\n" +
      "[sensors]\ntemperature_file.1 = " + dir.path() + "/temp\ntemperature_period_ms = 100\n";
  auto parsed = ParseConfig(text, "t.conf");
  ASSERT_TRUE(parsed.ok()) << parsed.error().ToString();
  LinuxBoardConfig config = *parsed;
  config.settings.temperature[0].source = ChannelSource::kLinuxFile;
  config.settings.temperature[1].source = ChannelSource::kLinuxFile;  // no file
  std::vector<std::string> log;
  LinuxBoard::Options options;
  options.log = [&log](const std::string& line) { log.push_back(line); };
  hal::mock::MockClock clock;
  hal::mock::MockCan controller(&clock, nullptr, 256);
  LinuxBoard board(config, options);
  ASSERT_TRUE(board.Open(&controller, nullptr).ok());
  const auto& channels = board.app().app().thermal().channels();
  auto run_until = [&](ChannelState state) {
    for (int i = 0; i < 300 && channels.state(0) != state; ++i) {  // up to 3 s
      pollfd p{board.tick_timer().fd(), POLLIN, 0};
      ::poll(&p, 1, 10);
      board.OnTimer();
    }
    return channels.state(0);
  };
  ASSERT_EQ(run_until(ChannelState::kValid), ChannelState::kValid);
  EXPECT_EQ(channels.value_cC(0), 2450);
  ASSERT_EQ(std::remove((dir.path() + "/temp").c_str()), 0);
  ASSERT_EQ(run_until(ChannelState::kOutOfRange), ChannelState::kOutOfRange);
  EXPECT_EQ(channels.value_cC(0), 2450);  // held
  board.Shutdown();
  int named = 0;
  for (const std::string& line : log) {
    if (line.find("temperature_file.1") != std::string::npos &&
        line.find("No such file") != std::string::npos)
      ++named;
    if (line.find("channel 2's source is a Linux file") != std::string::npos) ++named;
  }
  EXPECT_EQ(named, 2);
}

}  // namespace
}  // namespace volcomp::linux_board
