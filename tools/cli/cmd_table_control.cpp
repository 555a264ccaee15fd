// `volcomp activate | deactivate`: table control over CAN (0x2101 = 1 / 0).
//
// Activate first reads the staged table back and checks it against the board's installation
// (board_fit.hpp): a table the board would clamp or rate-limit is refused unless --allow-clamp.
#include <ostream>
#include <string>

#include "board_fit.hpp"
#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;

// The staged table, read back and checked against the installation before it is activated.
Outcome CheckStagedFits(canopen_client::CanSession& s,
                        uint8_t node,
                        bool allow_clamp,
                        std::ostream& warnings) {
  VOLCOMP_TRY_ASSIGN(const uint32_t status,
                     ReadNumber(s, ObjectId::kTableStatus, "the table status (0x2102)"));
  const canopen::StagedState staged = canopen::DecodeTableStatus(status).staged;
  if (staged != canopen::StagedState::kVerified && staged != canopen::StagedState::kComplete) {
    return Outcome::Ok();  // nothing to check: the board refuses the activation and says why
  }
  VOLCOMP_TRY_ASSIGN(
      const std::vector<uint8_t> bytes,
      Checked(s.ReadDomain(ObjectId::kTableData), "reading back the staged table (0x2100)"));
  VOLCOMP_TRY_ASSIGN(
      const image::LoadedImage img,
      image::LoadedImage::FromBytes(bytes, "the staged table of node " + std::to_string(node)));
  VOLCOMP_TRY(RequireTableFits(s, img.view(), allow_clamp, warnings));
  return Outcome::Ok();
}

// Writes `command` and reads back the table then active.
Expected<JsonValue> Control(const CanConnection& can,
                            TableCommand command,
                            bool allow_clamp,
                            std::ostream& warnings) {
  const bool activate = command == TableCommand::kActivate;
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(can));
  canopen_client::CanSession& s = *session;
  if (activate) VOLCOMP_TRY(CheckStagedFits(s, can.node, allow_clamp, warnings));
  VOLCOMP_TRY(Required(canopen_client::EnsureWritable(s)));
  canopen_client::SdoOutcome written = s.Write(ObjectId::kTableControl, canopen::Value(command));
  if (activate) written = canopen_client::WithStagingReason(s, std::move(written));
  VOLCOMP_TRY(Checked(std::move(written), std::string(activate ? "activation" : "deactivation") +
                                              " refused by node " + std::to_string(can.node)));
  VOLCOMP_TRY_ASSIGN(const uint32_t crc,
                     ReadNumber(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)"));
  VOLCOMP_TRY_ASSIGN(const uint32_t id,
                     ReadNumber(s, ObjectId::kActiveTableId, "the active table id (0x2103)"));
  JsonValue d = JsonValue::Object();
  d.Set("command", activate ? "activate" : "deactivate");
  d.Set("node", unsigned{can.node});
  d.Set("active_table_id", uint64_t{id});
  d.Set("active_crc32", tools::Hex32(crc));
  d.Set("exit_code", tools::kExitOk);
  return d;
}

void ControlText(const JsonValue& d, std::ostream& out) {
  out << (d.get("command")->string == "activate" ? "activated" : "deactivated") << ": node "
      << d.get("node")->integer << " active table id " << d.get("active_table_id")->integer
      << ", CRC-32 " << d.get("active_crc32")->string << "\n";
}

Expected<Output> RunControl(Args& args, Context& ctx, TableCommand command) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const bool allow_clamp = command == TableCommand::kActivate && args.Flag("--allow-clamp");
  args.Flag("--json");  // the command layer prints the data as JSON
  VOLCOMP_TRY(args.Finish());
  VOLCOMP_TRY_ASSIGN(JsonValue data, Control(can, command, allow_clamp, ctx.err));
  if (ctx.json) ControlText(data, ctx.err);  // the message beside the object, as documented
  return Output{std::move(data), ControlText, {}};
}

Expected<Output> RunActivate(Args& args, Context& ctx) {
  return RunControl(args, ctx, TableCommand::kActivate);
}

Expected<Output> RunDeactivate(Args& args, Context& ctx) {
  return RunControl(args, ctx, TableCommand::kDeactivate);
}

}  // namespace

const Command& ActivateCommand() {
  static const Command kCommand{
      "activate",
      "activate the staged, verified table (axes referenced and at rest)",
      "",
      Join({CanOptions(),
            {{"--allow-clamp", nullptr, nullptr, nullptr, nullptr,
              "activate a table the board would clamp (0x2015) or rate-limit (0x2016)"}},
            JsonResultOption()}),
      RunActivate,
      "The staged table is read back and checked against the board's installation first: axis\n"
      "count, names and units per step (0x2012) must match; a table whose largest correction\n"
      "exceeds the max correction (0x2015), or whose gradient times the fastest input rates\n"
      "(0x201E) exceeds the max correction rate (0x2016), is refused unless --allow-clamp."};
  return kCommand;
}

const Command& DeactivateCommand() {
  static const Command kCommand{"deactivate",
                                "deactivate the active table (the correction ramps out)", "",
                                Join({CanOptions(), JsonResultOption()}), RunDeactivate};
  return kCommand;
}

}  // namespace volcomp::cli
