// `volcomp activate | deactivate | reference`: table control and referencing over CAN.
//
// Activate first reads the staged table back and checks it against the board's installation
// (board_fit.hpp): a table the board would clamp or rate-limit is refused unless --allow-clamp.
// Reference refuses axes the board does not have (0x2000:4).
#include <cstdio>
#include <iostream>
#include <string>

#include "board_fit.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"
#include "volcomp/tools/json.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;

// The staged table, read back and checked against the installation before it is activated.
void CheckStagedFits(canopen_client::CanSession& s, uint8_t node, bool allow_clamp) {
  uint32_t word = 0;
  Check(s.Read(ObjectId::kTableStatus, &word), "reading the table status (0x2102)");
  const canopen::StagedState staged = canopen::DecodeTableStatus(word).staged;
  if (staged != canopen::StagedState::kVerified && staged != canopen::StagedState::kComplete) {
    return;  // nothing to check: the board refuses the activation and says why
  }
  std::vector<uint8_t> bytes;
  Check(s.UploadDomain(ObjectId::kTableData, &bytes), "reading back the staged table (0x2100)");
  const image::LoadedImage img(bytes, "the staged table of node " + std::to_string(node));
  RequireTableFits(s, img.view(), allow_clamp);
}

int Control(Args& args, canopen::TableCommand command, const char* done) {
  const CanOptions can = ParseCanOptions(args);
  const bool allow_clamp =
      command == canopen::TableCommand::kActivate && args.flag("--allow-clamp");
  const bool json = args.flag("--json");
  args.finish();
  return OverTheBus([&] {
    auto s = OpenSession(can);
    if (command == canopen::TableCommand::kActivate) CheckStagedFits(*s, can.node, allow_clamp);
    Require(canopen_client::EnsureWritable(*s));
    canopen_client::SdoResult r = s->Write(ObjectId::kTableControl, canopen::Value(command));
    if (command == canopen::TableCommand::kActivate) r = canopen_client::WithStagingReason(*s, r);
    Check(r,
          std::string(command == canopen::TableCommand::kActivate ? "activation" : "deactivation") +
              " refused by node " + std::to_string(can.node));
    uint32_t crc = 0, id = 0;
    Check(s->Read(ObjectId::kActiveTableCrc, &crc), "reading the active CRC-32 (0x2104)");
    Check(s->Read(ObjectId::kActiveTableId, &id), "reading the active table id (0x2103)");
    std::fprintf(json ? stderr : stdout, "%s: node %u active table id %u, CRC-32 0x%08X\n", done,
                 can.node, id, crc);
    if (json) {  // one object on stdout; failures: RunCommand's {"command", "exit_code", "error"}
      JsonWriter w(std::cout);
      w.begin_object();
      w.key("command").value(command == canopen::TableCommand::kActivate ? "activate"
                                                                         : "deactivate");
      w.key("node").value(unsigned{can.node});
      w.key("active_table_id").value(uint64_t{id});
      w.key("active_crc32").value(Hex32(crc));
      w.key("exit_code").value(0);
      w.end_object();
      std::cout << "\n";
    }
    return 0;
  });
}

// "1,2,3" -> the bit mask of those axes (1..6); spaces are ignored.
uint32_t AxisMask(const std::string& list) {
  const auto bad = [&] {
    return UsageError("--axes takes axis numbers 1..6, e.g. 1,2,3 (got \"" + list + "\")");
  };
  uint32_t mask = 0;
  bool expect_axis = true;
  for (const char c : list) {
    if (c == ' ') continue;
    if (expect_axis && c >= '1' && c <= '6') {
      mask |= 1u << (c - '1');
    } else if (expect_axis || c != ',') {
      throw bad();
    }
    expect_axis = !expect_axis;
  }
  if (expect_axis) throw bad();  // empty, or a trailing comma
  return mask;
}

}  // namespace

int RunActivate(Args& args) { return Control(args, canopen::TableCommand::kActivate, "activated"); }
int RunDeactivate(Args& args) {
  return Control(args, canopen::TableCommand::kDeactivate, "deactivated");
}

int RunReference(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const std::string axes = args.value("--axes").value_or("");
  args.finish();
  const uint32_t asked = axes.empty() ? 0 : AxisMask(axes);
  return OverTheBus([&] {
    auto s = OpenSession(can);
    uint32_t count = 0;
    Check(s->Read(ObjectId::kAxisCountConfig, &count), "reading the axis count (0x2000:4)");
    const uint32_t all = count >= 6 ? 0x3Fu : (1u << count) - 1u;
    if ((asked & ~all) != 0) {
      throw InputError("--axes " + axes + ": node " + std::to_string(can.node) + " has " +
                       std::to_string(count) + " axes (0x2000:4), axis numbers 1.." +
                       std::to_string(count));
    }
    const uint32_t mask = asked != 0 ? asked : all;
    Check(s->Write(ObjectId::kReferenceAxes, mask), "referencing");
    std::printf("node %u: reference requested for axes mask 0x%02X\n", can.node, mask);
    return 0;
  });
}

}  // namespace volcomp::tools
