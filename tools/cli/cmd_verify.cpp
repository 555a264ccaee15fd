// `volcomp verify IMAGE`: which table a board has active or staged; --readback reads the image
// it names back (the active one from 0x2109, or with --staged the staged one from 0x2100) and
// compares it byte by byte. Exit 1 for a different or absent table (a verdict, not an error), 3
// when the board cannot be reached.
#include <algorithm>
#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using tools::Hex32;

struct VerifyRequest {
  CanConnection can;
  std::string file;
  bool readback = false;
  bool staged = false;  // the staged table instead of the active one
};

// What the board holds.
struct BoardTables {
  uint32_t active_crc = 0, staged_crc = 0;
  bool has_active = false, has_staged = false;
  canopen::StagedState staged_state = canopen::StagedState::kEmpty;
};

Expected<VerifyRequest> ParseVerify(Args& args) {
  VerifyRequest req;
  VOLCOMP_TRY_ASSIGN(req.can, ParseCanOptions(args));
  req.readback = args.Flag("--readback");
  req.staged = args.Flag("--staged");
  args.Flag("--json");  // the command layer prints the data as JSON
  const auto files = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (files.size() != 1) return UsageFailure("expected one IMAGE file");
  req.file = files[0];
  return req;
}

Expected<BoardTables> ReadTables(canopen_client::CanSession& s) {
  BoardTables t;
  VOLCOMP_TRY_ASSIGN(t.active_crc,
                     ReadNumber(s, ObjectId::kActiveTableCrc, "the active CRC-32 (0x2104)"));
  VOLCOMP_TRY_ASSIGN(t.staged_crc,
                     ReadNumber(s, ObjectId::kStagedTableCrc, "the staged CRC-32 (0x2105)"));
  VOLCOMP_TRY_ASSIGN(const uint32_t status,
                     ReadNumber(s, ObjectId::kTableStatus, "the table status (0x2102)"));
  VOLCOMP_TRY_ASSIGN(const uint32_t state,
                     ReadNumber(s, ObjectId::kDeviceState, "the device state (0x2122)"));
  t.staged_state = canopen::DecodeTableStatus(status).staged;
  t.has_active = canopen::DecodeDeviceState(state).table_active;
  t.has_staged = t.staged_state == canopen::StagedState::kComplete ||
                 t.staged_state == canopen::StagedState::kVerified;
  return t;
}

// The verdict on the tables alone: the image active, staged (and verified), or neither.
const char* Verdict(const VerifyRequest& req, const BoardTables& t, uint32_t crc) {
  if (req.staged) {
    const bool staged =
        t.has_staged && t.staged_crc == crc && t.staged_state == canopen::StagedState::kVerified;
    return staged ? "staged" : "not staged";
  }
  if (t.has_active && t.active_crc == crc) return "active";
  if (t.has_staged && t.staged_crc == crc) return "staged, not active";
  return "neither active nor staged";
}

// Everything `verify` reports. `readback` is null when the table was not read back.
JsonValue VerifyData(const VerifyRequest& req,
                     const BoardTables& t,
                     uint32_t crc,
                     const JsonValue* readback,
                     const char* verdict) {
  const bool ok = std::string(verdict) == "active" || std::string(verdict) == "staged";
  JsonValue d = JsonValue::Object();
  d.Set("command", "verify");
  d.Set("node", unsigned{req.can.node});
  d.Set("image_crc32", Hex32(crc));
  d.Set("active_crc32", t.has_active ? JsonValue(Hex32(t.active_crc)) : JsonValue());
  d.Set("staged_crc32", t.has_staged ? JsonValue(Hex32(t.staged_crc)) : JsonValue());
  d.Set("table", req.staged ? "staged" : "active");
  if (readback != nullptr) d.Set("readback", *readback);
  d.Set("verdict", verdict);
  d.Set("exit_code", ok ? tools::kExitOk : tools::kExitFailed);
  return d;
}

void VerifyText(const JsonValue& d, std::ostream& out) {
  const auto crc_or_none = [&](const char* key) {
    const JsonValue* v = d.get(key);
    return v->is_null() ? std::string("none") : v->string;
  };
  const int64_t node = d.get("node")->integer;
  const std::string& table = d.get("table")->string;
  out << "image CRC-32 " << d.get("image_crc32")->string << "; node " << node << ": active "
      << crc_or_none("active_crc32") << ", staged " << crc_or_none("staged_crc32") << "\n";
  if (const JsonValue* r = d.get("readback")) {
    out << "read back the " << r->get("table")->string << " table, " << r->get("bytes")->integer
        << " bytes: "
        << (r->get("identical")->boolean ? "identical to the image" : "DIFFERENT from the image")
        << "\n";
  }
  const std::string& verdict = d.get("verdict")->string;
  if (verdict == "no table to read back") {
    out << "no " << table << " table on node " << node << " to read back\n";
  } else if (verdict == "staged") {
    out << "verified: the image is staged and verified on node " << node << "\n";
  } else if (verdict == "not staged") {
    out << "the image is not the staged table of node " << node << "\n";
  } else if (verdict == "active") {
    out << "verified: the image is the active table\n";
  } else if (verdict == "staged, not active") {
    out << "the image is staged and verified but not active (run `volcomp activate`)\n";
  } else if (verdict == "neither active nor staged") {
    out << "the image is neither active nor staged on node " << node << "\n";
  }  // "different": the readback line says it
}

Expected<Output> RunVerify(Args& args, Context& ctx) {
  VOLCOMP_TRY_ASSIGN(const VerifyRequest req, ParseVerify(args));
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage img, image::ReadImageFile(req.file));
  const uint32_t crc = img.view().crc32;
  VOLCOMP_TRY_ASSIGN(const auto session, OpenSession(req.can));
  VOLCOMP_TRY_ASSIGN(const BoardTables t, ReadTables(*session));
  const char* verdict = Verdict(req, t, crc);
  JsonValue readback;
  if (req.readback) {
    if (req.staged ? !t.has_staged : !t.has_active) {
      verdict = "no table to read back";
    } else {
      VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> data,
                         Checked(session->ReadDomain(req.staged ? ObjectId::kTableData
                                                                : ObjectId::kActiveTableData),
                                 req.staged ? "reading back the staged table (0x2100)"
                                            : "reading back the active table (0x2109)"));
      const bool same =
          data.size() == img.size() && std::equal(data.begin(), data.end(), img.data());
      readback = JsonValue::Object();
      readback.Set("table", req.staged ? "staged" : "active");
      readback.Set("bytes", static_cast<int64_t>(data.size()));
      readback.Set("identical", same);
      if (!same) verdict = "different";
    }
  }
  JsonValue data = VerifyData(req, t, crc, readback.is_null() ? nullptr : &readback, verdict);
  const int code = static_cast<int>(data.get("exit_code")->integer);
  if (ctx.json) VerifyText(data, ctx.err);  // the messages beside the object, as documented
  return Output{std::move(data), VerifyText, {}, code};
}

}  // namespace

const Command& VerifyCommand() {
  static const Command kCommand{
      "verify",
      "check which table a board has active or staged",
      "IMAGE",
      Join({CanOptions(),
            {{"--readback", nullptr, nullptr, nullptr, nullptr,
              "read the table back (the active one, or the staged one with --staged) and compare "
              "it byte by byte"},
             {"--staged", nullptr, nullptr, nullptr, nullptr,
              "verify the staged table instead of the active one"}},
            JsonResultOption()}),
      RunVerify,
      "Exit 0 when the board has the image (active, or staged with --staged), 1 when it has\n"
      "another table or none, 3 when the board cannot be reached."};
  return kCommand;
}

}  // namespace volcomp::cli
