// The checked-in EDS must be exactly what the object dictionary definition generates, and its
// defaults must be what a board without stored settings reports.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "volcomp/canopen/identity.hpp"
#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen_client/eds_writer.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/sim/sim_sdo_host.hpp"

namespace volcomp {
namespace {

TEST(Eds, CheckedInFileMatchesTheObjectDictionary) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  ASSERT_NE(root, nullptr);
  std::ifstream f(std::string(root) + "/docs/volcomp.eds");
  ASSERT_TRUE(f) << "docs/volcomp.eds missing: run `volcomp eds -o docs/volcomp.eds`";
  std::stringstream checked_in;
  checked_in << f.rdbuf();
  std::ostringstream generated;
  canopen_client::WriteEds(generated);
  EXPECT_EQ(checked_in.str(), generated.str())
      << "docs/volcomp.eds is out of date: run `volcomp eds -o docs/volcomp.eds`";
  // Spot checks of the content.
  const std::string eds = generated.str();
  EXPECT_NE(eds.find("[2100]\nParameterName=Table data\nObjectType=0x7\nDataType=0x000F\n"
                     "AccessType=rw\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[1018sub1]\nParameterName=Vendor-ID"), std::string::npos);
  EXPECT_NE(eds.find("DefaultValue=$NODEID+0x580"), std::string::npos);
  // What a TPDO may map: the produced ro numbers, nothing else (CiA 306 PDOMapping).
  EXPECT_NE(eds.find("[2122]\nParameterName=Device state\nObjectType=0x7\nDataType=0x0006\n"
                     "AccessType=ro\nDefaultValue=0x0000\nPDOMapping=1"),
            std::string::npos);
  EXPECT_NE(eds.find("[2138sub1]\nParameterName=Applied correction steps axis 1\nObjectType=0x7\n"
                     "DataType=0x0003\nAccessType=ro\nDefaultValue=0\nPDOMapping=1"),
            std::string::npos);
  EXPECT_NE(eds.find("AccessType=rw\nDefaultValue=$NODEID+0x180\nPDOMapping=0"), std::string::npos);
  EXPECT_NE(eds.find("NrOfTXPDO=2\n"), std::string::npos);
  // The RPDOs: their COB-IDs follow the node-ID, their static mappings name the command word
  // (RPDO1) and the temperatures (RPDO2: 0x2150:1-4, RPDO3: 0x2150:5-8), the rw objects an RPDO
  // carries.
  EXPECT_NE(eds.find("NrOfRXPDO=3\n"), std::string::npos);
  EXPECT_NE(eds.find("[1401sub1]\nParameterName=COB-ID used by RPDO\nObjectType=0x7\n"
                     "DataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x300\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[1602sub4]\nParameterName=Application object 4\nObjectType=0x7\n"
                     "DataType=0x0007\nAccessType=const\nDefaultValue=0x21500810\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[2150sub8]\nParameterName=Temperature 0.01 C channel 8\nObjectType=0x7\n"
                     "DataType=0x0003\nAccessType=rw\nDefaultValue=0\nPDOMapping=1"),
            std::string::npos);
  EXPECT_NE(eds.find("[1400sub1]\nParameterName=COB-ID used by RPDO\nObjectType=0x7\n"
                     "DataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x200\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[1600sub1]\nParameterName=Application object 1\nObjectType=0x7\n"
                     "DataType=0x0007\nAccessType=const\nDefaultValue=0x21270010\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[2127]\nParameterName=Command word\nObjectType=0x7\nDataType=0x0006\n"
                     "AccessType=rw\nDefaultValue=0x0000\nPDOMapping=1"),
            std::string::npos);
}

std::string CheckedInEds() {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  if (root == nullptr) return "";
  std::ifstream f(std::string(root) + "/docs/volcomp.eds");
  std::stringstream text;
  text << f.rdbuf();
  return text.str();
}

struct EdsEntry {
  uint16_t index = 0;
  uint8_t sub = 0;
  std::string access, default_value;
};

// The (sub-)entries of an EDS text with their access type and default value, read as CiA 306
// lays them out ([XXXX] or [XXXXsubN] sections of key=value lines).
std::vector<EdsEntry> ParseEds(const std::string& text) {
  std::vector<EdsEntry> out;
  const std::regex section(R"(^\[([0-9A-F]{4})(sub([0-9A-F]+))?\]$)");
  std::istringstream in(text);
  std::string line;
  bool in_entry = false;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, section)) {
      out.push_back({static_cast<uint16_t>(std::stoul(m[1], nullptr, 16)),
                     static_cast<uint8_t>(m[3].matched ? std::stoul(m[3], nullptr, 16) : 0), "",
                     ""});
      in_entry = true;
    } else if (!line.empty() && line[0] == '[') {
      in_entry = false;
    } else if (in_entry && line.rfind("AccessType=", 0) == 0) {
      out.back().access = line.substr(11);
    } else if (in_entry && line.rfind("DefaultValue=", 0) == 0) {
      out.back().default_value = line.substr(13);
    }
  }
  return out;
}

TEST(Eds, DefaultsAreWhatAFreshBoardReports) {
  const std::string eds = CheckedInEds();
  ASSERT_FALSE(eds.empty()) << "docs/volcomp.eds not found (VOLCOMP_SOURCE_DIR)";
  std::map<std::pair<uint16_t, uint8_t>, EdsEntry> entries;
  for (const EdsEntry& e : ParseEds(eds)) entries[{e.index, e.sub}] = e;
  auto default_of = [&](uint16_t index, uint8_t sub) {
    return entries[{index, sub}].default_value;
  };
  // The drive timing a fresh board runs with: 200 ns pulses at up to 2 MHz, above the 1 MHz input.
  EXPECT_EQ(default_of(0x2019, 1), "0x000000C8");
  EXPECT_EQ(default_of(0x201D, 1), "0x001E8480");
  EXPECT_EQ(default_of(0x201E, 1), "0x000F4240");

  // A board without stored settings, read over the simulated bus.
  sim::SimBus bus(1000000);
  sim::SimulatedBoard board(bus, sim::SimulatedBoardOptions());
  sim::Endpoint& pc = bus.Attach("pc");
  ASSERT_TRUE(board.Start().ok());
  sim::SimSdoHost host(bus, board, pc, board.app().settings().node_id);
  host.Idle(2000000);
  canopen_client::NodeObjects node(host.Link(), host.node());
  int compared = 0;
  for (const auto& [key, e] : entries) {
    const bool configuration = (e.index >= 0x2000 && e.index <= 0x201F) || e.index == 0x1015 ||
                               e.index == 0x1017 || e.index == 0x2121;
    if (!configuration || e.access == "wo" || e.default_value.empty()) continue;
    const canopen::ObjectEntry* entry = canopen::FindEntry(e.index, e.sub);
    ASSERT_NE(entry, nullptr) << std::hex << e.index << " sub " << int{e.sub};
    const auto r = node.Read(entry->id);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const uint32_t value = *r;
    EXPECT_EQ(value, static_cast<uint32_t>(std::stoll(e.default_value, nullptr, 0)))
        << entry->name << " (" << std::hex << e.index << " sub " << int{e.sub}
        << "): the board reports " << std::dec << value << ", the EDS says " << e.default_value;
    ++compared;
  }
  // 0x1015, 0x1017 and 0x2121, 0x2000 sub 0-4, 15 axis arrays.
  EXPECT_EQ(compared, 3 + 5 + 16 * 7);
  EXPECT_EQ(default_of(0x1015, 0), "0x0064");  // EMCY inhibit time 10 ms (100 x 100 us)

  // The TPDOs (0x1800.., 0x1A00..): each default the fresh board reports, $NODEID resolved.
  int pdo_compared = 0;
  for (const auto& [key, e] : entries) {
    if (e.index < 0x1800 || e.index > 0x1BFF) continue;
    const canopen::ObjectEntry* entry = canopen::FindEntry(e.index, e.sub);
    ASSERT_NE(entry, nullptr) << std::hex << e.index << " sub " << int{e.sub};
    const auto r = node.Read(entry->id);
    ASSERT_TRUE(r.ok()) << r.error().message;
    std::string text = e.default_value;
    uint32_t expected = 0;
    if (text.rfind("$NODEID+", 0) == 0) {
      expected = board.app().settings().node_id +
                 static_cast<uint32_t>(std::stoul(text.substr(8), nullptr, 0));
    } else {
      expected = static_cast<uint32_t>(std::stoll(text, nullptr, 0));
    }
    EXPECT_EQ(*r, expected) << std::hex << e.index << " sub " << int{e.sub} << ": " << text;
    ++pdo_compared;
  }
  EXPECT_EQ(pdo_compared, 2 * 5 + 2 * 9);
  EXPECT_EQ(default_of(0x1800, 1), "$NODEID+0x180");
  EXPECT_EQ(default_of(0x1801, 1), "$NODEID+0x280");
  EXPECT_EQ(default_of(0x1A00, 1), "0x21220010");  // device state, 16 bits
  EXPECT_EQ(default_of(0x1A01, 4), "0x21380610");  // axis 6's correction steps, 16 bits

  // 0x1009: the EDS and the node agree. The default is the board's; the EDS declares the value
  // read-only (not const) and names the simulated node's value in its comments; the simulated
  // node reports exactly that.
  EXPECT_EQ(default_of(0x1009, 0), canopen::HardwareVersion(canopen::Hardware::kBoard));
  EXPECT_EQ((entries[{0x1009, 0}].access), "ro");
  const auto hardware = node.ReadString(canopen::ObjectId::kHardwareVersion);
  ASSERT_TRUE(hardware.ok()) << hardware.error().message;
  EXPECT_EQ(*hardware, canopen::HardwareVersion(canopen::Hardware::kSimulator));
  const size_t comments = eds.find("[Comments]\n");
  ASSERT_NE(comments, std::string::npos);
  const std::string comment_block = eds.substr(comments, eds.find("\n\n", comments) - comments);
  EXPECT_NE(comment_block.find("0x1009"), std::string::npos) << comment_block;
  EXPECT_NE(comment_block.find("\"" + *hardware + "\" on the simulated node"), std::string::npos)
      << comment_block;
  // Software version and device name: one definition too.
  EXPECT_EQ(default_of(0x100A, 0), canopen::kSoftwareVersionText);
  const auto software = node.ReadString(canopen::ObjectId::kSoftwareVersion);
  ASSERT_TRUE(software.ok());
  EXPECT_EQ(*software, canopen::kSoftwareVersionText);
}

}  // namespace
}  // namespace volcomp
