// `sdo write` checks the value against the object dictionary before anything is sent: the type's
// range and the entry's limits (od_entries.def), read-only and non-numeric objects.
#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "volcomp/canopen_client/value_check.hpp"

namespace volcomp::testing {
namespace {

using canopen::ObjectId;

// The payload, or empty with the refusal's message in *why (always kInvalidArgument).
std::vector<uint8_t> Encode(ObjectId id, const std::string& text, std::string* why) {
  const Expected<std::vector<uint8_t>> p =
      canopen_client::EncodeWriteValue(canopen::Entry(id), text);
  if (p.ok()) return *p;
  EXPECT_EQ(p.error().code, Error::kInvalidArgument) << p.error().message;
  *why = p.error().message;
  return {};
}

TEST(SdoValue, TheTypeAndTheLimitsBoundTheValue) {
  std::string why;
  // 0x2010 axis name: UNSIGNED8, 0..255.
  EXPECT_EQ(Encode(ObjectId::kAxisName1, "88", &why), (std::vector<uint8_t>{88}));
  EXPECT_TRUE(Encode(ObjectId::kAxisName1, "300", &why).empty());
  EXPECT_NE(why.find("0..255"), std::string::npos) << why;
  EXPECT_TRUE(Encode(ObjectId::kAxisName1, "-1", &why).empty());
  // 0x2018 home position: INTEGER32, negative values as two's complement.
  EXPECT_EQ(Encode(ObjectId::kAxisHome1, "-5000", &why),
            (std::vector<uint8_t>{0x78, 0xEC, 0xFF, 0xFF}));
  EXPECT_TRUE(Encode(ObjectId::kAxisHome1, "2147483648", &why).empty());
  // 0x2000:1 node-ID: limits 1..127 from the dictionary.
  EXPECT_TRUE(Encode(ObjectId::kNodeIdConfig, "0", &why).empty());
  EXPECT_NE(why.find("1..127"), std::string::npos) << why;
  EXPECT_EQ(Encode(ObjectId::kNodeIdConfig, "0x7F", &why), (std::vector<uint8_t>{0x7F}));
  // 0x2015 max correction: 0..65536.
  EXPECT_TRUE(Encode(ObjectId::kAxisMaxCorrection1, "65537", &why).empty());
  // Read-only and non-numeric objects, and text that is no integer.
  EXPECT_TRUE(Encode(ObjectId::kActiveTableCrc, "1", &why).empty());
  EXPECT_NE(why.find("read-only"), std::string::npos) << why;
  EXPECT_TRUE(Encode(ObjectId::kTableData, "1", &why).empty());
  EXPECT_TRUE(Encode(ObjectId::kAxisHome1, "12abc", &why).empty());
  EXPECT_NE(why.find("not an integer"), std::string::npos) << why;
}

// The cases: 300 into an UNSIGNED8 was stored as 44, -1 as 255. Now refused with exit 2
// before the bus is even opened (the bus here does not exist: its error would name it).
TEST(VolcompCli, SdoWriteRefusesOutOfRangeValuesBeforeSending) {
  for (const char* value : {"300", "-1"}) {
    const CliResult r = RunCli({"sdo", "write", "2010:1", value, "--can", "slcan-tcp:127.0.0.1:1"});
    EXPECT_EQ(r.code, tools::kExitUsage) << r.err;
    EXPECT_NE(r.err.find("0..255"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nothing was sent"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("127.0.0.1"), std::string::npos) << r.err;
  }
  const CliResult unknown =
      RunCli({"sdo", "write", "2999:1", "1", "--can", "slcan-tcp:127.0.0.1:1"});
  EXPECT_EQ(unknown.code, tools::kExitUsage) << unknown.err;
}

// No board (nothing listens on the port): a communication failure, exit 3, not a refusal.
TEST(VolcompCli, NoBoardIsACommunicationFailure) {
  for (const std::vector<std::string>& words :
       {std::vector<std::string>{"sdo", "read", "2104:0"}, {"activate"}, {"reference"}}) {
    std::vector<std::string> w = words;
    w.insert(w.end(), {"--can", "slcan-tcp:127.0.0.1:1"});
    const CliResult r = RunCli(w);
    EXPECT_EQ(r.code, tools::kExitCommunication) << words[0] << ": " << r.err;
  }
}

}  // namespace
}  // namespace volcomp::testing
