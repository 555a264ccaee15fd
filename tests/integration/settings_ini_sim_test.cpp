// The board's settings file (hosted/ settings_ini.hpp, `volcomp config`) against the real firmware
// on the simulated bus: a file applied (objects written, stored, NMT reset node) is what the board
// runs (read from the firmware itself, not over SDO), a file saved from one board and applied to a
// fresh one saves back identically, and the tool's consistency verdict is the board's own store
// verdict.
#include <gtest/gtest.h>

#include <memory>

#include "expected_value.hpp"
#include "volcomp/canopen_client/board_settings_io.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/hosted/settings_ini.hpp"
#include "volcomp/sim/sim_sdo_host.hpp"

namespace volcomp {
namespace {

using canopen_client::Differences;

BoardSettings ParseBoardIni(const std::string& text, const std::string& source) {
  const hosted::IniExpected<BoardSettings> r = hosted::ParseSettingsIni(text, source);
  EXPECT_TRUE(r.ok()) << r.error().ToString();
  return r.ok() ? *r : BoardSettings();
}

const char* const kMachine =
    "[board]\n"
    "tick_hz = 25000\n"
    "heartbeat_ms = 500\n"
    "axes = X Y Z C\n"
    "[axis X]\n"
    "units_per_step = 0.0005\n"
    "home_position = -5000\n"
    "max_correction = 800\n"
    "drive_max_rate_hz = 200000\n"
    "max_input_rate_hz = 150000\n"
    "[axis Y]\n"
    "[axis Z]\n"
    "output_format = cw_ccw\n"
    "[axis C]\n"
    "kind = rotary\n"
    "units_per_step = 0.001\n";

// One fresh simulated board (factory settings, node 16, write-enable input set) and a PC.
struct Bench {
  Bench() : bus(1000000), board(bus, Options()), pc(bus.Attach("pc")) {
    EXPECT_TRUE(board.Start().ok());
    host = std::make_unique<sim::SimSdoHost>(bus, board, pc, 16);
    host->Idle(2000000);
    node = std::make_unique<canopen_client::NodeObjects>(host->Link(), 16);
  }
  static sim::SimulatedBoardOptions Options() {
    sim::SimulatedBoardOptions o;
    o.write_enable_input = true;
    return o;
  }
  void ResetNode() {
    CanFrame f;
    f.id = 0;
    f.dlc = 2;
    f.data[0] = 0x81;  // NMT reset node (CiA 301)
    f.data[1] = 16;
    pc.Send(f);
    host->Idle(5000000);
  }
  // What `volcomp config apply` does, in steps.
  void Apply(const BoardSettings& wanted) {
    size_t written = 0;
    testing::CheckOk(canopen_client::WriteObjects(
        *node, Differences(testing::ValueOf(canopen_client::ReadSettings(*node)), wanted),
        &written));
    EXPECT_TRUE(testing::ValueOf(canopen_client::SettingsPending(*node)));
    testing::CheckOk(canopen_client::StoreSettings(*node));
    ResetNode();
    EXPECT_FALSE(testing::ValueOf(canopen_client::SettingsPending(*node)));
  }

  sim::SimBus bus;
  sim::SimulatedBoard board;
  sim::Endpoint& pc;
  std::unique_ptr<sim::SimSdoHost> host;
  std::unique_ptr<canopen_client::NodeObjects> node;
};

TEST(BoardIniSim, AnAppliedFileIsWhatTheBoardRuns) {
  Bench a;
  a.Apply(ParseBoardIni(kMachine, "m.ini"));
  // The settings in force, from the firmware (values as the file states them).
  const BoardSettings& s = a.board.app().settings();
  EXPECT_EQ(s.board.tick_hz, 25000u);
  EXPECT_EQ(a.board.app().control_tick().compensation_divider(), CompensationDivider(25000));
  EXPECT_EQ(s.heartbeat_ms, 500);
  EXPECT_EQ(s.board.axis_count, 4);
  EXPECT_EQ(s.board.axis[0].resolution_e9, 500000u);
  EXPECT_EQ(s.board.axis[0].home_position_steps, -5000);
  EXPECT_EQ(s.board.axis[0].max_correction_steps, 800);
  EXPECT_EQ(s.board.axis[0].drive.max_rate_hz, 200000u);
  EXPECT_EQ(s.board.axis[2].output_format, PulseFormat::kCwCcw);
  EXPECT_EQ(s.board.axis[3].name, 'C');
  EXPECT_EQ(s.board.axis[3].kind, table::AxisKind::kRotary);
  EXPECT_EQ(s.board.axis[1].max_correction_steps, 1000);  // left out: the factory value
}

// 0x2124 is the configuration in force (compared with the firmware's own, not over SDO): an edit
// changes the objects at once and what runs only after store and reset node.
TEST(BoardIniSim, SettingsInForceAreWhatTheFirmwareRunsNotTheEditedCopy) {
  Bench a;
  const BoardSettings wanted = ParseBoardIni(kMachine, "m.ini");
  size_t written = 0;
  testing::CheckOk(canopen_client::WriteObjects(
      *a.node, Differences(testing::ValueOf(canopen_client::ReadSettings(*a.node)), wanted),
      &written));
  EXPECT_GT(written, 0u);
  // The communication parameters are in force as soon as written (CiA 301); the rest is not.
  BoardSettings runs = a.board.app().settings();
  EXPECT_EQ(runs.heartbeat_ms, 1000);
  runs.heartbeat_ms = 500;
  EXPECT_TRUE(
      Differences(testing::ValueOf(canopen_client::ReadSettingsInForce(*a.node)), runs).empty());
  EXPECT_FALSE(
      Differences(testing::ValueOf(canopen_client::ReadSettingsInForce(*a.node)), wanted).empty());
  EXPECT_EQ(testing::ValueOf(canopen_client::ReadSettingsInForce(*a.node))
                .board.axis[0]
                .max_correction_steps,
            1000);
  testing::CheckOk(canopen_client::StoreSettings(*a.node));
  a.ResetNode();
  const BoardSettings in_force = testing::ValueOf(canopen_client::ReadSettingsInForce(*a.node));
  EXPECT_TRUE(Differences(in_force, a.board.app().settings()).empty());
  EXPECT_EQ(in_force.board.axis[0].max_correction_steps, 800);
  EXPECT_EQ(in_force.heartbeat_ms, 500);
}

TEST(BoardIniSim, SavedFromOneBoardAppliedToAFreshOneSavesIdentically) {
  Bench a;
  a.Apply(ParseBoardIni(kMachine, "m.ini"));
  const std::string first =
      hosted::FormatSettingsIni(testing::ValueOf(canopen_client::ReadSettings(*a.node)), {"saved"});
  Bench b;
  b.Apply(ParseBoardIni(first, "first.ini"));
  const std::string second =
      hosted::FormatSettingsIni(testing::ValueOf(canopen_client::ReadSettings(*b.node)), {"saved"});
  EXPECT_EQ(first, second);
  // Both boards run the same configuration (from the firmware, every stored object).
  EXPECT_TRUE(Differences(a.board.app().settings(), b.board.app().settings()).empty());
  // Nothing left to do for a board that has the file in force.
  EXPECT_TRUE(Differences(testing::ValueOf(canopen_client::ReadSettings(*b.node)),
                          ParseBoardIni(second, "s.ini"))
                  .empty());
}

TEST(BoardIniSim, TheFilesConsistencyVerdictIsTheBoards) {
  // Written object by object, the board takes each value (each is within its limits) and refuses
  // the set at the store (0x06090030); the file with the same values is refused before anything
  // is written.
  const std::string bad = "[board]\naxes = X\n[axis X]\ndrive_max_rate_hz = 1001000\n";
  const hosted::IniExpected<BoardSettings> refused = hosted::ParseSettingsIni(bad, "bad.ini");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().ToFailure().code, Error::kInputInvalid);
  EXPECT_NE(refused.error().ToString().find("bad.ini:3: [axis X]: drive_max_rate_hz 1001000"),
            std::string::npos)
      << refused.error().ToString();
  Bench a;
  BoardSettings s = BoardSettings();
  s.board.axis_count = 1;
  s.board.axis[0].drive.max_rate_hz = 1001000;
  size_t written = 0;
  testing::CheckOk(canopen_client::WriteObjects(
      *a.node, Differences(testing::ValueOf(canopen_client::ReadSettings(*a.node)), s), &written));
  EXPECT_EQ(written, 2u);
  const Outcome store_refused = canopen_client::StoreSettings(*a.node);
  ASSERT_FALSE(store_refused.ok()) << "the board stored an inconsistent set";
  EXPECT_NE(store_refused.error().message.find("0x06090030"), std::string::npos)
      << store_refused.error().message;
  // One more Hz of drive rate: both accept.
  s.board.axis[0].drive.max_rate_hz = 1002000;
  const std::string good = "[board]\naxes = X\n[axis X]\ndrive_max_rate_hz = 1002000\n";
  EXPECT_TRUE(Differences(ParseBoardIni(good, "good.ini"), s).empty());
  testing::CheckOk(canopen_client::WriteObjects(
      *a.node, Differences(testing::ValueOf(canopen_client::ReadSettings(*a.node)), s), &written));
  const Outcome stored = canopen_client::StoreSettings(*a.node);
  EXPECT_TRUE(stored.ok()) << stored.error().message;
}

}  // namespace
}  // namespace volcomp
