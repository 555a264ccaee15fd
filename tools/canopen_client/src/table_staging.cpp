// The table-staging steps.
#include "volcomp/canopen_client/table_staging.hpp"

#include <cstdio>

#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::canopen_client {

using canopen::ObjectId;
using canopen::TableCommand;
using tools::Hex32;

std::string AbortHint(canopen::SdoAbort abort_code) {
  switch (abort_code) {
    case canopen::SdoAbort::kCannotStore:
      return "the board is write-protected: set its write-enable input or let the tool unlock it";
    case canopen::SdoAbort::kDeviceState:
      return "the axes must be referenced (homed) and at rest";
    case canopen::SdoAbort::kNoData:
      return "no verified table is staged: upload one first";
    default:
      return "";
  }
}

std::string VerifyHint(canopen::SdoAbort abort_code) {
  switch (abort_code) {
    case canopen::SdoAbort::kCannotStore:
      return "the staged image is not valid for this board: upload a table built for it";
    case canopen::SdoAbort::kDeviceState:
      return "an upload is in progress: wait for it to end";
    case canopen::SdoAbort::kNoData:
      return "nothing complete is staged: upload a table first";
    default:
      return "";
  }
}

SdoFailure Explain(SdoFailure f, const std::string& step) {
  const std::string hint = AbortHint(f.abort);
  f.message = step + ": " + f.message + (hint.empty() ? "" : "; " + hint);
  return f;
}

std::string StagingFailureReason(NodeObjects& node) {
  const SdoExpected<uint32_t> word = node.Read(ObjectId::kTableStatus);
  if (!word.ok()) return "";
  const canopen::TableStatus st = canopen::DecodeTableStatus(*word);
  if (st.staged == canopen::StagedState::kEmpty) return "nothing is staged (upload a table first)";
  if (st.staged != canopen::StagedState::kFailed || st.error == Error::kOk) return "";
  std::string why = std::string(ErrorText(st.error)) + " (" + ErrorName(st.error) + ")";
  if (st.error == Error::kTransferAbortedByClient) {
    // The client's own abort code (0x210A): what the client saw, not what the board found.
    if (const SdoExpected<uint32_t> code = node.Read(ObjectId::kTransferAbortCode); code.ok()) {
      why += ": aborted by the client, code " + Hex32(*code) + " (" +
             canopen::SdoAbortText(canopen::AbortFromCode(*code)) + ")";
    }
  }
  return why;
}

ConfigFinding SettingsFinding(NodeObjects& node) {
  const SdoExpected<uint32_t> word = node.Read(ObjectId::kSettingsCheck);
  return word.ok() ? canopen::DecodeSettingsCheck(*word).finding : ConfigFinding();
}

std::string SettingsRefusalReason(NodeObjects& node) {
  const ConfigFinding f = SettingsFinding(node);
  if (f.rule == ConfigRule::kNone) return "";
  const std::string axis = f.axis != 0 ? "axis " + std::to_string(f.axis) + ": " : std::string();
  return axis + ConfigRuleText(f.rule);
}

SdoFailure WithStagingReason(NodeObjects& node, SdoFailure f) {
  if (!f.by_server) return f;
  const std::string why = StagingFailureReason(node);
  if (!why.empty()) f.message += "; the board says: " + why;
  return f;
}

std::string TableCommandStep(TableCommand command) {
  const char* what = "";
  switch (command) {
    case TableCommand::kDeactivate:
      what = "deactivating";
      break;
    case TableCommand::kActivate:
      what = "activating";
      break;
    case TableCommand::kClear:
      what = "clearing the staging bank";
      break;
    case TableCommand::kVerify:
      what = "verifying on the board";
      break;
  }
  char object[32];
  std::snprintf(object, sizeof object, " (0x%04X = %u)",
                canopen::Entry(ObjectId::kTableControl).index,
                static_cast<unsigned>(canopen::Value(command)));
  return what + std::string(object);
}

SdoOutcome WriteTableCommand(NodeObjects& node, TableCommand command) {
  SdoOutcome r = node.Write(ObjectId::kTableControl, canopen::Value(command));
  if (command == TableCommand::kVerify || command == TableCommand::kActivate) {
    r = WithStagingReason(node, std::move(r));
  }
  if (command == TableCommand::kVerify && !r.ok()) {
    // Verification needs no write access: its refusals say what is wrong with the staged data.
    SdoFailure f = r.error();
    const std::string hint = VerifyHint(f.abort);
    f.message = TableCommandStep(command) + ": " + f.message + (hint.empty() ? "" : "; " + hint);
    return Fail(std::move(f));
  }
  return Explain(std::move(r), TableCommandStep(command));
}

SdoOutcome EnsureWritable(NodeObjects& node) {
  VOLCOMP_TRY_ASSIGN(const uint32_t writable,
                     Explain(node.Read(ObjectId::kWriteAccess), "reading write access (0x2111)"));
  if (writable != 0) return SdoOutcome::Ok();
  return Explain(node.Write(ObjectId::kUnlock, canopen::kUnlockSignature), "unlocking (0x2110)");
}

SdoOutcome PrepareStaging(NodeObjects& node) {
  VOLCOMP_TRY(EnsureWritable(node));
  return WriteTableCommand(node, TableCommand::kClear);
}

SdoOutcome VerifyStaged(NodeObjects& node, uint32_t image_crc) {
  VOLCOMP_TRY(WriteTableCommand(node, TableCommand::kVerify));
  VOLCOMP_TRY_ASSIGN(const uint32_t staged, Explain(node.Read(ObjectId::kStagedTableCrc),
                                                    "reading the staged CRC-32 (0x2105)"));
  if (staged != image_crc) {
    return SdoFail(Error::kImageBadCrc,
                   "the board staged CRC-32 " + Hex32(staged) + ", expected " + Hex32(image_crc));
  }
  return SdoOutcome::Ok();
}

}  // namespace volcomp::canopen_client
