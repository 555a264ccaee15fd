// `volcomp activate | deactivate | reference`: table control and referencing over CAN.
#include <cstdio>

#include "can_options.hpp"
#include "commands.hpp"
#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/image/axis_units.hpp"

namespace volcomp::tools {
namespace {

using canopen::ObjectId;
constexpr uint32_t kUnlockSignature = 0x6B6C6E75;  // "unlk", see firmware/board_objects.hpp

void Require(const canopen_client::SdoResult& r, const std::string& what) {
  if (r.ok) return;
  std::string hint;
  if (r.abort_code == canopen::kAbortDeviceState) {
    hint = " -- the axes must be referenced (homed) and at rest";
  } else if (r.abort_code == canopen::kAbortNoData) {
    hint = " -- no verified table is staged";
  } else if (r.abort_code == canopen::kAbortCannotStore) {
    hint = " -- the board is write-protected";
  }
  throw InputError(what + ": " + r.message + hint);
}

void UnlockIfNeeded(canopen_client::CanSession& s) {
  uint32_t writable = 0;
  Require(s.Read(ObjectId::kWriteAccess, &writable), "reading write access");
  if (writable == 0) Require(s.Write(ObjectId::kUnlock, kUnlockSignature), "unlocking");
}

int Control(Args& args, uint8_t command, const char* done) {
  const CanOptions can = ParseCanOptions(args);
  args.finish();
  auto s = OpenSession(can);
  UnlockIfNeeded(*s);
  Require(s->Write(ObjectId::kTableControl, command),
          std::string(command == 1 ? "activation" : "deactivation") + " refused by node " +
              std::to_string(can.node));
  uint32_t crc = 0, id = 0;
  Require(s->Read(ObjectId::kActiveTableCrc, &crc), "reading the active CRC-32");
  Require(s->Read(ObjectId::kActiveTableId, &id), "reading the active table id");
  std::printf("%s: node %u active table id %u, CRC-32 0x%08X\n", done, can.node, id, crc);
  return 0;
}

}  // namespace

int RunActivate(Args& args) { return Control(args, 1, "activated"); }
int RunDeactivate(Args& args) { return Control(args, 0, "deactivated"); }

int RunReference(Args& args) {
  const CanOptions can = ParseCanOptions(args);
  const std::string axes = args.value("--axes").value_or("");
  args.finish();
  uint32_t mask = 0x3F;
  if (!axes.empty()) {
    mask = 0;
    for (const std::string& item : {axes}) {
      size_t start = 0;
      while (start <= item.size()) {
        const size_t end = std::min(item.find(',', start), item.size());
        const long long a = std::stoll(item.substr(start, end - start));
        if (a < 1 || a > 6) throw UsageError("--axes takes axis numbers 1..6, e.g. 1,2,3");
        mask |= 1u << (a - 1);
        start = end + 1;
      }
    }
  }
  auto s = OpenSession(can);
  Require(s->Write(ObjectId::kReferenceAxes, mask), "referencing");
  std::printf("node %u: reference requested for axes mask 0x%02X\n", can.node, mask);
  return 0;
}

}  // namespace volcomp::tools
