// `volcomp activate | deactivate | reference`: table control and referencing over CAN.
#include <cstdio>
#include <string>

#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;

int Control(Args& args, canopen::TableCommand command, const char* done) {
  const CanOptions can = ParseCanOptions(args);
  args.finish();
  auto s = OpenSession(can);
  Require(canopen_client::EnsureWritable(*s));
  Check(s->Write(ObjectId::kTableControl, canopen::Value(command)),
        std::string(command == canopen::TableCommand::kActivate ? "activation" : "deactivation") +
            " refused by node " + std::to_string(can.node));
  uint32_t crc = 0, id = 0;
  Check(s->Read(ObjectId::kActiveTableCrc, &crc), "reading the active CRC-32 (0x2104)");
  Check(s->Read(ObjectId::kActiveTableId, &id), "reading the active table id (0x2103)");
  std::printf("%s: node %u active table id %u, CRC-32 0x%08X\n", done, can.node, id, crc);
  return 0;
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
  const uint32_t mask = axes.empty() ? 0x3Fu : AxisMask(axes);
  auto s = OpenSession(can);
  Check(s->Write(ObjectId::kReferenceAxes, mask), "referencing");
  std::printf("node %u: reference requested for axes mask 0x%02X\n", can.node, mask);
  return 0;
}

}  // namespace volcomp::tools
