// The volcomp-fw-linux configuration file: the shipped example, defaults, every kind of mistake
// with its line number, and the round trip through FormatConfig.
#include "volcomp/fw_linux/config_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace volcomp::fw_linux {
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
  const auto r = LoadConfigFile(SourceDir() + "/firmware/linux/volcomp-fw-linux.conf");
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

TEST(ConfigFileTest, FormatParsesBackToTheSameConfiguration) {
  const auto loaded_a = LoadConfigFile(SourceDir() + "/firmware/linux/volcomp-fw-linux.conf");
  ASSERT_TRUE(loaded_a.ok()) << loaded_a.error().ToString();
  const LinuxBoardConfig& a = *loaded_a;
  const std::string text = FormatConfig(a);
  const auto parsed_b = ParseConfig(text, "formatted");
  ASSERT_TRUE(parsed_b.ok()) << parsed_b.error().ToString() << "\n" << text;
  const LinuxBoardConfig& b = *parsed_b;
  EXPECT_EQ(FormatConfig(b), text);
  firmware::BoardSettings sa = a.settings, sb = b.settings;
  uint8_t ra[firmware::kSettingsBytes], rb[firmware::kSettingsBytes];
  firmware::SerializeSettings(sa, ra);
  firmware::SerializeSettings(sb, rb);
  EXPECT_EQ(std::string(ra, ra + sizeof ra), std::string(rb, rb + sizeof rb));
}

TEST(ConfigFileTest, MistakesAreNamedWithTheirLine) {
  const std::string base = kMinimal;
  struct Case {
    std::string text;
    std::string expect;
  };
  const Case cases[] = {
      {"[board]\nnode_id = 200\n", "test.conf:2: node_id: value above 127"},
      {"[board]\nnod_id = 1\n", "test.conf:2: unknown key 'nod_id' in [board]"},
      {base + "[boards]\n", "test.conf:14: unknown section [boards]"},
      {base + "[gpio]\nestop = gpiochip0:6 active-high\n", "unknown line flag 'active-high'"},
      {base + "[gpio]\nbackend = sysfs\n", "expected gpiod, fake"},
      {base + "[gpio]\nhome2 = gpiochip0:2\n", "home2 is wired but the board has only 2 axes"},
      {base + "[gateway]\nfeedback = sometimes\n", "expected sync or latest"},
      {base + "[axis Y]\nunits_per_step = 0.001\n", "[axis Y] is not in [board] axes"},
      {"[board]\naxes = X Q\n", "axis name 'Q'"},
      {"[board]\naxes = X X\n", "axis X given twice"},
      {"[board]\naxes = X\n[axis X]\nkind = linear\n", "needs units_per_step"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 0.0000000001\n", "at most 9 decimals"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 0\n", "must be above zero"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\ntarget_pdo = 0x201\n", "COB-ID:OFFSET"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\ntarget_pdo = 0x201:5\n", "above 4"},
      {"[board]\naxes = X\n[axis X]\nunits_per_step = 1\nmax_accel = 5000000\n[can]\n"
       "controller = a\n[flash]\ntables = t\n",
       "max_rate / max_accel do not fit tick_hz 1000"},
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
  EXPECT_EQ(r.error().message, "node_id: value above 127");
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

}  // namespace
}  // namespace volcomp::fw_linux
