// The `volcomp-sim` command line in process: help, dispatch, options refused with their message
// and exit code 2, failures of a run with exit code 1, a short benchmark's report.
#include "volcomp/sim/command_line.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "sim_runner.hpp"

namespace volcomp::sim {
namespace {

TEST(SimCommandLine, HelpListsEveryCommand) {
  const SimRun help = Sim({"help"});
  EXPECT_EQ(help.code, 0);
  EXPECT_EQ(help.out.rfind("usage: volcomp-sim COMMAND [options]\n\n  node [--slcan-tcp PORT", 0),
            0u)
      << help.out;
  EXPECT_NE(help.out.find("\n  bench-upload [--bitrate N] [--nodes N]\n"), std::string::npos);
  EXPECT_NE(help.out.find("\n  demo [--seed N] [--report DIR]"), std::string::npos);
  EXPECT_EQ(Sim({"--help"}).out, help.out);
  const SimRun none = Sim({});
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.out, help.out);
  const SimRun unknown = Sim({"bogus"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(unknown.err, "volcomp-sim: unknown command \"bogus\"\n");
  EXPECT_EQ(unknown.out, help.out);
}

TEST(SimCommandLine, DemoOptionsAreRefusedWithTheirReason) {
  const struct {
    std::vector<std::string> words;
    const char* message;
  } cases[] = {
      {{"demo", "--bogus"}, "unexpected argument \"--bogus\""},
      {{"demo", "extra"}, "unexpected argument \"extra\""},
      {{"demo", "--seed", "-1"}, "--seed must be >= 0"},
      {{"demo", "--seed", "x"}, "option --seed: \"x\" is not an integer"},
      {{"demo", "--machine", "foo"}, "--machine must be ideal or worn"},
      {{"demo", "--without", "sag"}, "--without needs --machine worn"},
      {{"demo", "--machine", "worn", "--without", "sag,foo"},
       "--without: unknown source \"foo\" (lost-motion, scatter, screw, thermal, sag, "
       "misalignment)"},
      {{"demo", "--points", "0"}, "--points must be 1..100000"},
      {{"demo", "--laser-noise-um", "-1"}, "--laser-noise-um must be >= 0"},
      {{"demo", "--tracker-noise-um", "-0.5"}, "--tracker-noise-um must be >= 0"},
  };
  for (const auto& c : cases) {
    const SimRun r = Sim(c.words);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_EQ(r.err, std::string("volcomp-sim demo: ") + c.message + "\n");
    EXPECT_EQ(r.out, "");
  }
}

TEST(SimCommandLine, DemoWithAModelFileThatCannotBeReadFails) {
  const SimRun r = Sim({"demo", "--model", "/nonexistent/machine.conf", "--quick"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err.rfind("volcomp-sim demo: /nonexistent/machine.conf: ", 0), 0u) << r.err;
}

TEST(SimCommandLine, NodeOptionsAreRefusedWithTheirReason) {
  const struct {
    std::vector<std::string> words;
    const char* message;
  } cases[] = {
      {{"node", "--bogus"}, "unexpected argument \"--bogus\""},
      {{"node", "--node", "200"}, "--node must be 1..127"},
      {{"node", "--bitrate", "5"}, "--bitrate must be a whole kbit/s from 10000 to 1000000"},
      {{"node", "--bitrate", "125500"}, "--bitrate must be a whole kbit/s from 10000 to 1000000"},
      {{"node", "--slcan-tcp"}, "option --slcan-tcp needs a value"},
      {{"node", "--slcan-tcp", "abc"}, "option --slcan-tcp: \"abc\" is not an integer"},
      {{"node", "--slcan-tcp", "70000"}, "--slcan-tcp must be a port 0..65535"},
      {{"node", "--slcan-tcp", "0", "--socketcan", "vcan0"},
       "give one of --slcan-tcp, --slcan-pty, --socketcan"},
      {{"node", "--slcan-pty", "a", "b"}, "unexpected argument \"b\""},
      {{"node", "--slcan-tcp", "0", "stray"}, "unexpected argument \"stray\""},
  };
  for (const auto& c : cases) {
    const SimRun r = Sim(c.words);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_EQ(r.err, std::string("volcomp-sim node: ") + c.message + "\n");
  }
}

TEST(SimCommandLine, BenchUploadReportsTheTransfer) {
  const SimRun r = Sim({"bench-upload", "--nodes", "5"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("upload of a 5x5x5 int16 grid (868 bytes) over the simulated 1000 kbit/s "
                        "bus:\n  block download  ",
                        0),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("\n  activated: yes, active CRC-32 0x"), std::string::npos) << r.out;
  const SimRun nodes = Sim({"bench-upload", "--nodes", "1"});
  EXPECT_EQ(nodes.code, 2);
  EXPECT_EQ(nodes.err, "volcomp-sim bench-upload: --nodes must be 2..1024\n");
  const SimRun bitrate = Sim({"bench-upload", "--bitrate", "0"});
  EXPECT_EQ(bitrate.code, 2);
  EXPECT_EQ(bitrate.err, "volcomp-sim bench-upload: --bitrate must be > 0 bit/s\n");
}

}  // namespace
}  // namespace volcomp::sim
