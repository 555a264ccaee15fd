// The CAN commands in-process against a simulated board (the firmware on the simulated bus,
// served over SLCAN-TCP on a thread paced to the wall clock, as `volcomp-sim node` does): their
// text is a layout of the JSON they report, their verdicts set the exit code, and a board that
// is not there is a communication failure.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "cli_runner.hpp"
#include "test_tables.hpp"
#include "volcomp/can_io/slcan_server.hpp"
#include "volcomp/sim/bus_bridge.hpp"
#include "volcomp/sim/realtime.hpp"
#include "volcomp/sim/simulated_board.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::testing {
namespace {

using tools::JsonValue;

// A simulated board (node 16, factory settings) behind an SLCAN-TCP server.
class SimulatedNode {
 public:
  explicit SimulatedNode(const BoardSettings& settings = BoardSettings())
      : bus_(1000000), board_(bus_, Options(settings)), ext_(bus_.Attach("external")) {
    auto server = can_io::SlcanServer::CreateTcp("127.0.0.1", 0);
    EXPECT_TRUE(server.ok()) << server.error().message;
    if (!server.ok()) return;
    server_ = std::move(server).value();
    EXPECT_TRUE(board_.Start().ok());
    thread_ = std::thread([this] { Serve(); });
  }
  ~SimulatedNode() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::string spec() const { return server_ ? server_->client_spec() : "slcan-tcp:127.0.0.1:1"; }

 private:
  static sim::SimulatedBoardOptions Options(const BoardSettings& settings) {
    sim::SimulatedBoardOptions o;
    o.settings = settings;
    o.write_enable_input = true;
    return o;
  }
  void Serve() {
    sim::SlcanBridge bridge(bus_, *server_, ext_);
    const sim::RealtimeClock clock;
    while (!stop_) {
      sim::AdvanceInEventOrder(bus_, board_, clock.Now());
      auto wait = clock.Until(sim::NextEventTime(bus_, board_));
      if (wait > std::chrono::microseconds(1000)) wait = std::chrono::microseconds(1000);
      if (!bridge.Serve(wait).ok()) return;
    }
  }

  sim::SimBus bus_;
  sim::SimulatedBoard board_;
  sim::Endpoint& ext_;
  std::unique_ptr<can_io::SlcanServer> server_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

JsonValue Json(const CliResult& r) {
  const Expected<JsonValue> v = tools::ParseJson(r.out, "stdout");
  EXPECT_TRUE(v.ok()) << v.error().message << "\n" << r.out;
  return v.ok() ? *v : JsonValue();
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A 3-axis table for the board's factory installation (1 µm per step), written to a file.
std::string TableFile(const std::string& name, uint32_t id) {
  GridCase g;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {4, -100000, 50000};
  for (size_t i = 0; i < g.count(); ++i) g.i16.push_back(static_cast<int16_t>(256 * (i % 3)));
  const AlignedBytes img = WriteGridImage(g, id);
  const std::string path = ::testing::TempDir() + name + "_" + std::to_string(::getpid()) + ".vct";
  EXPECT_TRUE(
      tools::WriteFileBytes(path, std::vector<uint8_t>(img.data(), img.data() + img.size())).ok());
  return path;
}

class CanCommands : public ::testing::Test {
 protected:
  CanCommands() = default;
  explicit CanCommands(const BoardSettings& settings) : node_(settings) {}
  CliResult Run(std::vector<std::string> words) {
    words.insert(words.end(), {"--can", node_.spec()});
    return RunCli(words);
  }
  SimulatedNode node_;
};

TEST_F(CanCommands, StatusTextIsALayoutOfItsJson) {
  const CliResult json = Run({"status", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const JsonValue d = Json(json);
  const CliResult text = Run({"status"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_EQ(
      text.out.rfind("node 16: " + d.get("device_name")->string + " " +
                         d.get("software_version")->string + " (vendor " +
                         d.get("vendor_id")->string + ", product " + d.get("product_code")->string +
                         ", revision " + d.get("revision")->string + ", serial " +
                         std::to_string(d.get("serial_number")->integer) + ")",
                     0),
      0u)
      << text.out;
  EXPECT_TRUE(Contains(text.out, "\nstate: " + d.get("device_state_flags")->string + "\n"))
      << text.out;
  EXPECT_TRUE(Contains(text.out, "\nactive table: none (pass-through)\n")) << text.out;
  EXPECT_TRUE(
      Contains(text.out, "\nstaged table: " + d.get("staged_table")->get("state")->string + "\n"))
      << text.out;
  const auto& axes = d.get("axes")->array;
  ASSERT_EQ(axes.size(), 3u);
  for (const JsonValue& x : axes) {
    const std::string head = "axis " + std::to_string(x.get("axis")->integer) + " " +
                             x.get("name")->string + ": input " +
                             std::to_string(x.get("commanded_steps")->integer) +
                             " steps, machine not referenced, correction +0.000 µm (+0.000 steps, "
                             "max " +
                             std::to_string(x.get("max_correction_steps")->integer) + " = ";
    char um[32];
    std::snprintf(um, sizeof um, "%.3f µm)", x.get("max_correction_um")->number);
    EXPECT_TRUE(Contains(text.out, head + um)) << head << um << "\n" << text.out;
    // The µm are the steps at the axis's units per step (an outside check of the conversion).
    EXPECT_NEAR(x.get("max_correction_um")->number,
                static_cast<double>(x.get("max_correction_steps")->integer) *
                    x.get("units_per_step")->number * 1000,
                1e-9);
  }
  EXPECT_EQ(d.get("counters")->object.size(), 10u);
  EXPECT_TRUE(Contains(text.out, "\ncounters: can_rx_frames=")) << text.out;
  for (const auto& counter : d.get("counters")->object) {
    EXPECT_TRUE(Contains(text.out, " " + counter.first + "=")) << counter.first;
  }
}

// Channels 1 and 3 written over CAN (timeout 60 s, so a loaded machine cannot make them stale
// during a test), the others unused; no model in force.
BoardSettings TwoCanChannels() {
  BoardSettings settings;
  for (int ch : {0, 2}) {
    settings.temperature[ch].source = thermal::ChannelSource::kCanObject;
    settings.temperature[ch].timeout_ms = 60000;
  }
  return settings;
}

class CanCommandsThermal : public CanCommands {
 protected:
  CanCommandsThermal() : CanCommands(TwoCanChannels()) {}
};

// The thermal correction's channels: channel 1 written, channel 3 never.
TEST_F(CanCommandsThermal, StatusShowsTheConfiguredChannels) {
  ASSERT_EQ(Run({"sdo", "write", "2150:1", "2345"}).code, 0);
  const CliResult refused = Run({"sdo", "write", "2150:2", "2345"});  // channel 2: unused
  EXPECT_EQ(refused.code, 1);
  EXPECT_TRUE(Contains(refused.err, "abort 0x06010002")) << refused.err;
  const CliResult json = Run({"status", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const JsonValue d = Json(json);
  const JsonValue* t = d.get("thermal");
  ASSERT_NE(t, nullptr) << json.out;
  EXPECT_FALSE(t->get("model_in_force")->boolean);
  const auto& channels = t->get("channels")->array;
  ASSERT_EQ(channels.size(), 2u);
  EXPECT_EQ(channels[0].get("channel")->integer, 1);
  EXPECT_EQ(channels[0].get("state")->string, "valid");
  EXPECT_DOUBLE_EQ(channels[0].get("temperature_C")->number, 23.45);
  EXPECT_EQ(channels[0].get("faults")->integer, 0);
  EXPECT_EQ(channels[1].get("channel")->integer, 3);
  EXPECT_EQ(channels[1].get("state")->string, "waiting");  // configured, never written
  EXPECT_TRUE(t->get("axes")->array.empty());
  const CliResult text = Run({"status"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_TRUE(Contains(text.out,
                       "\nthermal: no model; channel 1 23.45 C valid (0 faults), channel 3 0.00 C "
                       "waiting (0 faults)\n"))
      << text.out;
}

// `monitor --csv`: a temperature and a state column for each channel in use when it starts (here
// channels 1 and 3), after the axes' columns, in every row.
TEST_F(CanCommandsThermal, MonitorCsvHasTheConfiguredChannels) {
  ASSERT_EQ(Run({"sdo", "write", "2150:1", "-125"}).code, 0);
  const CliResult r = Run({"monitor", "--csv", "--interval-ms", "100", "--duration", "0.35"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> lines;
  for (size_t at = 0; at < r.out.size();) {
    const size_t end = r.out.find('\n', at);
    lines.push_back(r.out.substr(at, end - at));
    at = end == std::string::npos ? r.out.size() : end + 1;
  }
  ASSERT_GE(lines.size(), 2u) << r.out;
  EXPECT_TRUE(Contains(lines[0], "_rate_limited,T1_C,T1_state,T3_C,T3_state,output_overruns,"))
      << lines[0];
  for (size_t i = 1; i < lines.size(); ++i) {
    EXPECT_TRUE(Contains(lines[i], ",-1.25,valid,0.00,waiting,")) << lines[i];
  }
}

// Without a channel in use (the factory settings), no temperature columns.
TEST_F(CanCommands, MonitorCsvWithoutChannelsHasNoTemperatureColumns) {
  const CliResult r = Run({"monitor", "--csv", "--interval-ms", "100", "--duration", "0.15"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string header = r.out.substr(0, r.out.find('\n'));
  EXPECT_TRUE(Contains(header, "Z_rate_limited,output_overruns,refused_actions,sdo_aborts"))
      << header;
}

TEST_F(CanCommands, UploadThenVerifyVerdictsAndExitCodes) {
  const std::string a = TableFile("a", 3);
  CliResult r = Run({"verify", a});
  EXPECT_EQ(r.code, 1) << r.err;  // a verdict, not an error: nothing on stderr
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(Contains(r.out, "the image is neither active nor staged on node 16")) << r.out;

  r = Run({"upload", a, "--quiet"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "staged and verified on node 16")) << r.out;

  r = Run({"verify", a, "--json"});
  EXPECT_EQ(r.code, 1) << r.err;
  JsonValue d = Json(r);
  EXPECT_EQ(d.get("verdict")->string, "staged, not active");
  EXPECT_EQ(d.get("exit_code")->integer, 1);
  EXPECT_TRUE(d.get("active_crc32")->is_null());
  EXPECT_EQ(d.get("staged_crc32")->string, d.get("image_crc32")->string);
  // The messages go to stderr beside the object.
  EXPECT_TRUE(Contains(r.err, "the image is staged and verified but not active")) << r.err;

  r = Run({"verify", a, "--staged", "--readback", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  d = Json(r);
  EXPECT_EQ(d.get("verdict")->string, "staged");
  EXPECT_TRUE(d.get("readback")->get("identical")->boolean);
  const CliResult text = Run({"verify", a, "--staged", "--readback"});
  EXPECT_EQ(text.code, 0) << text.err;
  EXPECT_EQ(text.out, "image CRC-32 " + d.get("image_crc32")->string +
                          "; node 16: active none, staged " + d.get("staged_crc32")->string +
                          "\nread back the staged table, " +
                          std::to_string(d.get("readback")->get("bytes")->integer) +
                          " bytes: identical to the image\n"
                          "verified: the image is staged and verified on node 16\n");
  std::remove(a.c_str());
}

TEST_F(CanCommands, ActivateRefusalSaysWhyAndActivationReportsTheTable) {
  CliResult r = Run({"activate", "--json"});
  EXPECT_EQ(r.code, 1);
  JsonValue d = Json(r);
  EXPECT_EQ(d.get("exit_code")->integer, 1);
  EXPECT_TRUE(Contains(d.get("error")->string, "the board says: nothing is staged"))
      << d.get("error")->string;

  const std::string a = TableFile("b", 5);
  ASSERT_EQ(Run({"upload", a, "--quiet"}).code, 0);
  r = Run({"upload", a, "--quiet", "--activate"});  // not referenced: staged, then refused
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(Contains(r.err,
                       "upload failed: activating (0x2101 = 1): node 16 refused 2101:00: "
                       "abort 0x08000022"))
      << r.err;
  ASSERT_EQ(Run({"reference", "--axes", "1,2,3"}).code, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // at rest
  r = Run({"activate", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  d = Json(r);
  EXPECT_EQ(d.get("command")->string, "activate");
  EXPECT_EQ(d.get("active_table_id")->integer, 5);
  EXPECT_EQ(r.err,
            "activated: node 16 active table id 5, CRC-32 " + d.get("active_crc32")->string + "\n");
  r = Run({"deactivate"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "deactivated: node 16 active table id 0, CRC-32 0x00000000\n");
  std::remove(a.c_str());
}

TEST_F(CanCommands, SdoReadsWritesAndTheBoardsReasons) {
  CliResult r = Run({"sdo", "write", "2018:1", "-5000"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "ok\n");
  EXPECT_EQ(Run({"sdo", "read", "2018:1"}).out, "-5000 (0xFFFFEC78)\n");
  EXPECT_EQ(Run({"sdo", "read", "2010:1"}).out, "88 (0x58)\n");
  EXPECT_EQ(Run({"sdo", "read", "1008:0"}).out, "volcomp\n");
  r = Run({"sdo", "read", "2999:0"});
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(Contains(r.err, "error: node 16 refused 2999:00: abort 0x06020000")) << r.err;
  r = Run({"sdo", "write", "2101:0", "4"});  // verify with nothing staged
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(Contains(r.err,
                       "writing 2101:0: node 16 refused 2101:00: abort 0x08000024 "
                       "(no data available); the board says: nothing is staged"))
      << r.err;
  r = Run({"sdo", "read", "zz"});
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(Contains(r.err, "object address \"zz\": use INDEX:SUB in hex")) << r.err;
}

TEST_F(CanCommands, ConfigShowTextIsALayoutOfItsJson) {
  ASSERT_EQ(Run({"sdo", "write", "2015:1", "800"}).code, 0);  // edited, not in force
  // 2.5 µm per step (0x2012 holds pm per step): 1 / 0.0025 mm = 400 steps per mm.
  ASSERT_EQ(Run({"sdo", "write", "2012:2", "2500000"}).code, 0);
  const CliResult json = Run({"config", "show", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const JsonValue d = Json(json);
  EXPECT_TRUE(d.get("settings_pending")->boolean);
  const CliResult text = Run({"config", "show"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_TRUE(Contains(text.out, "node 16: settings pending: ")) << text.out;
  int rows = 0;
  for (const JsonValue& x : d.get("objects")->array) {
    ++rows;
    if (x.get("object")->string == "2012:2") {
      EXPECT_EQ(x.get("steps_per_unit")->number, 400.0);
      EXPECT_EQ(x.get("resolution")->string, "400 steps/mm (2500 nm/step)");
    }
    if (x.get("object")->string != "2015:1") continue;
    EXPECT_EQ(x.get("value")->integer, 800);
    EXPECT_EQ(x.get("in_force")->integer, 1000);
    EXPECT_EQ(x.get("factory_text")->string, "1000");
  }
  EXPECT_GT(rows, 0);
  EXPECT_TRUE(Contains(text.out,
                       "\n2015:1  X    max_correction      800         1000        "
                       "1000        * ! steps"))
      << text.out;
  EXPECT_TRUE(Contains(text.out, " (value: 400 steps/mm (2500 nm/step))\n")) << text.out;
  EXPECT_TRUE(Contains(text.out, " (value: 1000 steps/mm (1000 nm/step))\n")) << text.out;
  EXPECT_TRUE(Contains(text.out, "(axes 4..6 are not used: --all shows their objects)"))
      << text.out;
}

// A drive with 2000 steps/s to spare beyond the 1 MHz input: a direction switch reaches that rate
// within one compensation period (50 kHz / 3) at 2000 * 50000 / 3 = 33 333 333 steps/s^2, below
// the factory 10^8 of 0x2020. `config apply` says so before it writes, `config show` for the
// settings in force; both in their JSON.
TEST_F(CanCommands, ConfigSaysWhereTheDirectionSwitchAccelerationIsBound) {
  const std::string ini = ::testing::TempDir() + "bound_" + std::to_string(::getpid()) + ".ini";
  ASSERT_TRUE(tools::WriteTextFile(ini,
                                   "[board]\naxes = X Y Z\n[axis X]\ndrive_max_rate_hz = 1002000\n"
                                   "[axis Y]\n[axis Z]\n")
                  .ok());
  const CliResult apply = Run({"config", "apply", ini, "--json"});
  ASSERT_EQ(apply.code, 0) << apply.err;
  const std::string line =
      "axis X: direction_switch_accel (2020:1) 100000000 steps/s2 takes effect as 33333333 "
      "steps/s2: it reaches the rate the drive has beyond the input within one period at 16666 Hz";
  EXPECT_TRUE(Contains(apply.err, line)) << apply.err;
  for (const CliResult& r : {apply, Run({"config", "show", "--json"})}) {
    const JsonValue d = Json(r);
    ASSERT_NE(d.get("switch_accel_bounds"), nullptr) << r.out;
    const auto& bounds = d.get("switch_accel_bounds")->array;
    ASSERT_EQ(bounds.size(), 1u) << r.out;
    EXPECT_EQ(bounds[0].get("object")->string, "2020:1");
    EXPECT_EQ(bounds[0].get("configured")->integer, 100000000);
    EXPECT_EQ(bounds[0].get("in_effect")->integer, 33333333);
    EXPECT_EQ(bounds[0].get("bound")->string, "drive rate");
  }
  const CliResult text = Run({"config", "show"});
  EXPECT_TRUE(Contains(text.out, "in force, " + line + "\n")) << text.out;
  std::remove(ini.c_str());
}

// The integrator's drive takes 2.5 us pulses and 2.5 us spaces: at most 200 kHz. A file that
// says 400 kHz passes the file check (the rules every board keeps: the CAN gateway never sends
// pulses), and the step/dir board refuses it at the store: `config apply` says the values, the
// limit and the fix, and undoes the edits; 200 kHz is applied.
TEST_F(CanCommands, ConfigApplySaysWhyTheBoardRefusesAPulseTimingAndUndoesTheEdits) {
  const std::string ini = ::testing::TempDir() + "pulse_" + std::to_string(::getpid()) + ".ini";
  const auto file = [&](int rate) {
    return "[board]\naxes = X Y Z\n[axis X]\npulse_width_ns = 2500\nstep_space_ns = 2500\n"
           "max_input_rate_hz = 190000\ndrive_max_rate_hz = " +
           std::to_string(rate) + "\n[axis Y]\n[axis Z]\n";
  };
  ASSERT_TRUE(tools::WriteTextFile(ini, file(400000)).ok());
  const CliResult refused = Run({"config", "apply", ini});
  EXPECT_NE(refused.code, 0);
  EXPECT_TRUE(Contains(refused.err,
                       "the board refuses the settings: [axis X]: drive_max_rate_hz 400000 is more "
                       "than the pulse timing allows: pulse_width_ns 2500 + step_space_ns 2500 = "
                       "5000 ns a step, at most 200000 Hz; set drive_max_rate_hz to at most "
                       "200000"))
      << refused.err;
  EXPECT_TRUE(Contains(refused.err, "edits written were undone")) << refused.err;
  const JsonValue after = Json(Run({"config", "show", "--json"}));
  EXPECT_FALSE(after.get("settings_pending")->boolean);
  for (const JsonValue& x : after.get("objects")->array) {
    if (x.get("object")->string == "201D:1") {
      EXPECT_EQ(x.get("value")->integer, 2000000);
    }
  }
  ASSERT_TRUE(tools::WriteTextFile(ini, file(200000)).ok());
  const CliResult applied = Run({"config", "apply", ini});
  EXPECT_EQ(applied.code, 0) << applied.err << applied.out;
  std::remove(ini.c_str());
}

TEST_F(CanCommands, NmtIsConfirmedByTheHeartbeat) {
  CliResult r = Run({"nmt", "stop"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "node 16: stop: heartbeat reports stopped\n");
  r = Run({"nmt", "start", "--no-wait"});
  EXPECT_EQ(r.out, "node 16: start sent (not confirmed: --no-wait)\n");
  r = Run({"nmt", "reset-comm"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "node 16: reset communication: boot-up seen, pre-operational\n");
}

// A node-ID nobody answers to: no answer is a communication failure (exit 3), naming the read.
TEST_F(CanCommands, NoAnswerIsACommunicationFailure) {
  const CliResult r = Run({"status", "--node", "99", "--timeout-ms", "50", "--json"});
  EXPECT_EQ(r.code, 3);
  const JsonValue d = Json(r);
  EXPECT_EQ(d.get("exit_code")->integer, 3);
  EXPECT_EQ(d.get("error")->string,
            "reading Vendor-ID: no response from node 99 (sent abort 0x05040000: SDO protocol "
            "timed out)");
}

}  // namespace
}  // namespace volcomp::testing
