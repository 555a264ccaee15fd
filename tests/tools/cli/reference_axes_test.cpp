// `volcomp reference --axes LIST`: a malformed list is a usage error, before any CAN traffic.
#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace volcomp::testing {
namespace {

TEST(VolcompCli, ReferenceRefusesMalformedAxisLists) {
  for (const char* list : {"x", "0", "7", "1,", ",1", "1,,2", "12", "1;2", "1 2", "-1"}) {
    const CliResult r = RunCli({"reference", "--can", "slcan-tcp:127.0.0.1:1", "--axes", list});
    EXPECT_EQ(r.code, 2) << list;
    EXPECT_NE(r.err.find("--axes takes axis numbers 1..6"), std::string::npos) << list << r.err;
  }
}

TEST(VolcompCli, ReferenceAcceptsAxisListsAndThenNeedsTheBus) {
  // A well-formed list passes parsing; the command then fails opening the (absent) bus: a
  // communication failure (exit 3).
  for (const char* list : {"1", "1,2,3", " 4 , 6 "}) {
    const CliResult r = RunCli({"reference", "--can", "slcan-tcp:127.0.0.1:1", "--axes", list});
    EXPECT_EQ(r.code, tools::kExitCommunication) << list << r.err;
    EXPECT_EQ(r.err.find("--axes"), std::string::npos) << list << r.err;
  }
}

}  // namespace
}  // namespace volcomp::testing
