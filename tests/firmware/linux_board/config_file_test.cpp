// The volcomp-fw-linux configuration file: the shipped example, defaults, every kind of mistake
// with its line number, the round trip through FormatConfig, and its [board] / [axis] settings
// read as the PC tool's board file reads them (one codec).
#include "volcomp/linux_board/config_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "volcomp/canopen/setting_objects.hpp"
#include "volcomp/hosted/settings_ini.hpp"

namespace volcomp::linux_board {
namespace {

std::string SourceDir() {
  const char* d = std::getenv("VOLCOMP_SOURCE_DIR");
  return d != nullptr ? d : ".";
}

const char kMinimal[] =
    "[board]\n"
    "axes = X Z\n"
    "[can]\n"
    "controller = can0\n"
    "drives = can1\n"
    "[axis X]\n"
    "units_per_step = 0.0005\n"
    "target_pdo = 0x201:2\n"
    "actual_pdo = 0x181:2\n"
    "[axis Z]\n"
    "units_per_step = 0.001\n"
    "[flash]\n"
    "tables = /tmp/t.bin\n";

std::string Error(const std::string& text) {
  const Expected<LinuxBoardConfig, ConfigError> r = ParseConfig(text, "test.conf");
  return r.ok() ? "" : r.error().ToString();
}

TEST(ConfigFileTest, TheShippedExampleIsValid) {
  const auto r = LoadConfigFile(SourceDir() + "/firmware/linux_board/volcomp-fw-linux.conf");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  const LinuxBoardConfig& c = *r;
  EXPECT_EQ(c.settings.node_id, 16);
  EXPECT_EQ(c.settings.board.tick_hz, 1000u);
  EXPECT_EQ(c.settings.board.axis_count, 3);
  EXPECT_EQ(c.settings.board.axis[1].name, 'Y');
  EXPECT_EQ(c.settings.board.axis[0].resolution_e9, 100000u);  // 0.0001 mm
  EXPECT_EQ(c.settings.board.axis[2].max_correction_steps, 2000);
  EXPECT_EQ(c.controller_iface, "can0");
  EXPECT_EQ(c.drives_iface, "can1");
  ASSERT_EQ(c.gateway.map_count, 6);
  EXPECT_EQ(c.gateway.map[0].cob_id, 0x201);
  EXPECT_EQ(c.gateway.map[0].field, gateway::PdoField::kTargetPosition);
  EXPECT_EQ(c.gateway.map[0].offset, 2);
  EXPECT_EQ(c.gateway.map[5].cob_id, 0x183);
  EXPECT_EQ(c.gateway.map[5].axis, 2);
  EXPECT_EQ(c.gateway.own_node_id, 16);
  EXPECT_EQ(c.gpio_backend, GpioBackendKind::kGpiod);
  const auto& estop = c.gpio.input[static_cast<int>(hal::InputLine::kEStop)];
  EXPECT_TRUE(estop.used);
  EXPECT_EQ(estop.offset, 6u);
  EXPECT_TRUE(estop.active_low);
  EXPECT_TRUE(c.enable_input);  // the enable line is wired
  EXPECT_EQ(c.table_file, "/var/lib/volcomp/tables.bin");
  EXPECT_EQ(c.table_bank_bytes, 512u * 1024u);
}

TEST(ConfigFileTest, MinimalFileGetsTheDefaults) {
  const auto r = ParseConfig(kMinimal, "test.conf");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  const LinuxBoardConfig& c = *r;
  EXPECT_EQ(c.settings.node_id, 0x10);
  EXPECT_EQ(c.settings.board.tick_hz, 1000u);
  EXPECT_EQ(c.settings.board.axis_count, 2);
  EXPECT_EQ(c.settings.board.axis[1].name, 'Z');
  EXPECT_EQ(c.settings.board.axis[0].resolution_e9, 500000u);
  EXPECT_EQ(c.settings.board.axis[1].resolution_e9, 1000000u);
  EXPECT_EQ(c.gateway.map_count, 2);
  EXPECT_EQ(c.gateway.feedback, gateway::FeedbackMode::kAtSync);
  EXPECT_EQ(c.gpio_backend, GpioBackendKind::kNone);
  EXPECT_FALSE(c.enable_input);
  EXPECT_TRUE(c.settings_file.empty());
  EXPECT_TRUE(c.flash_sync);
}

// The drive's increments per mm, as its datasheet says, in place of units_per_step.
TEST(ConfigFileTest, StepsPerUnitStandsInForUnitsPerStep) {
  const auto r = ParseConfig(
      "[board]\naxes = X\n[axis X]\nsteps_per_unit = 2000\n[can]\ncontroller = a\n"
      "[flash]\ntables = t\n",
      "test.conf");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  EXPECT_EQ(r->settings.board.axis[0].resolution_e9, 500000u);  // 0.0005 mm
}

TEST(ConfigFileTest, FormatParsesBackToTheSameConfiguration) {
  const auto loaded_a = LoadConfigFile(SourceDir() + "/firmware/linux_board/volcomp-fw-linux.conf");
  ASSERT_TRUE(loaded_a.ok()) << loaded_a.error().ToString();
  const LinuxBoardConfig& a = *loaded_a;
  const std::string text = FormatConfig(a);
  const auto parsed_b = ParseConfig(text, "formatted");
  ASSERT_TRUE(parsed_b.ok()) << parsed_b.error().ToString() << "\n" << text;
  const LinuxBoardConfig& b = *parsed_b;
  EXPECT_EQ(FormatConfig(b), text);
  BoardSettings sa = a.settings, sb = b.settings;
  uint8_t ra[kSettingsBytes], rb[kSettingsBytes];
  SerializeSettings(sa, ra);
  SerializeSettings(sb, rb);
  EXPECT_EQ(std::string(ra, ra + sizeof ra), std::string(rb, rb + sizeof rb));
}

// A channel fed by a sysfs file: its [temperature N] section (the PC tool's board file keys) and
// the file in [sensors]; both survive the round trip through FormatConfig.
TEST(ConfigFileTest, ATemperatureChannelFedByAFile) {
  const std::string text = std::string(kMinimal) +
                           "[sensors]\ntemperature_file.2 = /sys/class/hwmon/hwmon1/temp1_input\n"
                           "[temperature 2]\nsource = linux_file\nhigh_C = 60\n";
  const auto r = ParseConfig(text, "test.conf");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  EXPECT_EQ(r->settings.temperature[1].source, thermal::ChannelSource::kLinuxFile);
  EXPECT_EQ(r->settings.temperature[1].high_cC, 6000);
  EXPECT_EQ(r->settings.temperature[0].source, thermal::ChannelSource::kNone);
  EXPECT_EQ(r->temperature_files[1], "/sys/class/hwmon/hwmon1/temp1_input");
  const auto back = ParseConfig(FormatConfig(*r), "formatted");
  ASSERT_TRUE(back.ok()) << back.error().ToString();
  EXPECT_EQ(back->settings.temperature[1].source, thermal::ChannelSource::kLinuxFile);
  EXPECT_EQ(back->settings.temperature[1].high_cC, 6000);
  EXPECT_EQ(Error(std::string(kMinimal) + "[temperature 9]\nsource = can\n").empty(), false);
}

TEST(ConfigFileTest, MistakesAreNamedWithTheirLine) {
  const std::string base = kMinimal;
  struct Case {
    std::string text;
    std::string expect;
  };
  const Case cases[] = {
      {"[board]\nnode_id = 200\n", "test.conf:2: node_id = 200: above the highest value 127"},
      {"[board]\nnod_id = 1\n", "test.conf:2: unknown key 'nod_id' in [board]"},
      {base + "[boards]\n", "test.conf:14: unknown section [boards]"},
      {base + "[gpio]\nestop = gpiochip0:6 active-high\n", "unknown line flag 'active-high'"},
      {base + "[gpio]\nbackend = sysfs\n", "expected gpiod | fake"},
      {base + "[gpio]\nhome2 = gpiochip0:2\n", "home2 is wired but the board has only 2 axes"},
      {base + "[gateway]\nfeedback = sometimes\n", "expected sync | latest"},
      {base + "[axis Y]\nunits_per_step = 0.001\n", "[axis Y] is not one of [board] axes"},
      {"[board]\naxes = X Q\n", "axes: 'Q' is not an axis name"},
      {"[board]\naxes = X X\n", "axes: X given twice"},
      {"[board]\naxes = X\n[axis X]\nkind = linear\n", "needs units_per_step (or steps_per_unit)"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 0.0000000001\n", "at most 9 decimals"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 0\n",
       "units_per_step = 0: below the lowest value 1"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\ntarget_pdo = 0x201\n", "COB-ID:OFFSET"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\ntarget_pdo = 0x201:5\n",
       "target_pdo offset = 5: above the highest value 4"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\nmax_accel = 5000000\n[can]\n"
       "controller = a\n[flash]\ntables = t\n",
       "[axis X]: max_rate 2000 and max_accel 5000000 do not fit tick_hz 1000"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\n[flash]\ntables = t\n",
       "[can] controller = IFACE is required"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\n[can]\ncontroller = a\n",
       "[flash] tables = FILE is required"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\n[can]\ncontroller = a\ndrives = a\n",
       "must be different interfaces"},
      {"[board]\nnode_id = 1\nnode_id = 2\n", "test.conf:3: node_id: given twice"},
      {"node_id = 1\n", "test.conf:1: key outside a [section]"},
      {"[board\n", "test.conf:1: expected [section]"},
      {"[board]\nnode_id\n", "test.conf:2: expected key = value"},
      {"[board]\ntick_hz = fast\n", "expected a number, got 'fast'"},
      {"[board]\nenable_input = maybe\n", "expected true or false"},
      {base + "[axis Z]\n", "test.conf:14: section [axis Z] appears twice (first at line 10)"},
      // The mapping: the board's own heartbeat COB-ID (node 0x10) cannot be a PDO.
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\nactual_pdo = 0x710:0\n[can]\n"
       "controller = a\n[flash]\ntables = t\n",
       "the PDO mapping is invalid"},
  };
  for (const Case& c : cases) {
    const std::string why = Error(c.text);
    EXPECT_NE(why.find(c.expect), std::string::npos) << "got: " << why << "\nfor:\n" << c.text;
  }
}

TEST(ConfigFileTest, ErrorsCarryTheirSourceAndLine) {
  auto r = ParseConfig("[board]\nnode_id = 200\n", "test.conf");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().source, "test.conf");
  EXPECT_EQ(r.error().line, 2);
  EXPECT_EQ(r.error().message, "node_id = 200: above the highest value 127 of 2000:1 (Node-ID)");
  r = ParseConfig("[board]\naxes = X\n[axis X]\nunits_per_step = 1\n[flash]\ntables = t\n", "a");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 0);  // about the file, not a line
  EXPECT_EQ(r.error().ToString(), "a: [can] controller = IFACE is required");
  r = LoadConfigFile("/nonexistent-dir/volcomp.conf");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().ToString(),
            "/nonexistent-dir/volcomp.conf: cannot read the configuration file");
}

TEST(ConfigFileTest, CommentsNumbersAndBooleans) {
  const std::string text =
      "; a comment line\n"
      "[board]\n"
      "axes = X\n"
      "enable_input = off\n"
      "serial_number = 0xDEADBEEF\n"
      "[axis X]\n"
      "units_per_step = 0.001\n"
      "[can]\n"
      "controller = can0\n"
      "[flash]\n"
      "tables = t.bin\n"
      "[gateway]\n"
      "sync_cob_id = 0x81   # another SYNC COB-ID\n"
      "feedback = LATEST\n"
      "[gpio]\n"
      "backend = fake:/tmp/state#1\n"  // '#' not after a space: kept
      "enable = gpiochip0:5\n";
  const auto r = ParseConfig(text, "t");
  ASSERT_TRUE(r.ok()) << r.error().ToString();
  const LinuxBoardConfig& c = *r;
  EXPECT_EQ(c.gateway.sync_cob_id, 0x81);
  EXPECT_EQ(c.gateway.feedback, gateway::FeedbackMode::kLatest);
  EXPECT_EQ(c.fake_state_file, "/tmp/state#1");
  EXPECT_FALSE(c.enable_input);  // explicit, although the enable line is wired
  EXPECT_EQ(c.serial_number, 0xDEADBEEFu);
}

// One codec for both files: a board file as `volcomp config save` writes it is the [board] and
// [axis] part of a volcomp-fw-linux file, and both readers give the same settings; the Linux
// board writes its settings as the PC tool does.
TEST(ConfigFileTest, SharedKeysMeanTheSameInBothFiles) {
  BoardSettings s = LinuxBoardDefaults();
  s.node_id = 0x21;
  s.heartbeat_ms = 250;
  s.emcy_inhibit_100us = 7;
  s.board.tick_hz = 2000;
  s.board.axis_count = 2;
  s.board.axis[1].name = 'C';
  s.board.axis[1].kind = table::AxisKind::kRotary;
  s.board.axis[0].resolution_e9 = 500000;
  s.board.axis[1].resolution_e9 = 1000;
  s.board.axis[0].max_correction_steps = 800;
  s.board.axis[1].home_position_steps = -5000;
  s.board.axis[1].input_format = PulseFormat::kQuadrature;
  ASSERT_TRUE(ValidateSettings(s).ok());
  const std::string board_file = hosted::FormatSettingsIni(s, {"saved from a board"});
  const auto pc = hosted::ParseSettingsIni(board_file, "board.ini");
  ASSERT_TRUE(pc.ok()) << pc.error().ToString();
  const auto linux_file =
      ParseConfig(board_file + "\n[can]\ncontroller = can0\n[flash]\ntables = t.bin\n", "l.conf");
  ASSERT_TRUE(linux_file.ok()) << linux_file.error().ToString();
  for (const canopen::SettingObject& o : canopen::SettingObjects()) {
    EXPECT_EQ(o.get(*pc), o.get(s)) << canopen::Entry(o.id).name;
    EXPECT_EQ(o.get(linux_file->settings), o.get(s)) << canopen::Entry(o.id).name;
  }
  // Every settings line the PC tool writes, the Linux board writes too (the Linux keys beside).
  const std::string formatted = FormatConfig(*linux_file);
  std::istringstream lines(hosted::FormatSettingsIni(linux_file->settings, {}));
  for (std::string line; std::getline(lines, line);) {
    EXPECT_NE(formatted.find(line + "\n"), std::string::npos) << line << "\nin\n" << formatted;
  }
  // A key left out: the PC tool's file takes the factory value, the Linux board's its default
  // (tick 1 kHz); units_per_step is required on the Linux board only.
  const std::string bare = "[board]\naxes = X\n[axis X]\nunits_per_step = 0.001\n";
  EXPECT_EQ(hosted::ParseSettingsIni(bare, "b.ini")->board.tick_hz, 50000u);
  EXPECT_EQ(ParseConfig(bare + "[can]\ncontroller = a\n[flash]\ntables = t\n", "l.conf")
                ->settings.board.tick_hz,
            1000u);
  EXPECT_TRUE(hosted::ParseSettingsIni("[board]\naxes = X\n[axis X]\n", "b.ini").ok());
}

}  // namespace
}  // namespace volcomp::linux_board
