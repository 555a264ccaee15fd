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

SdoResult Explain(SdoResult r, const std::string& step) {
  if (r.ok) return r;
  const std::string hint = AbortHint(r.abort_code);
  r.message = step + ": " + r.message + (hint.empty() ? "" : "; " + hint);
  return r;
}

std::string StagingFailureReason(NodeObjects& node) {
  uint32_t word = 0;
  if (!node.Read(ObjectId::kTableStatus, &word).ok) return "";
  const canopen::TableStatus st = canopen::DecodeTableStatus(word);
  if (st.staged == canopen::StagedState::kEmpty) return "nothing is staged (upload a table first)";
  if (st.staged != canopen::StagedState::kFailed || st.error == Error::kOk) return "";
  return std::string(ErrorText(st.error)) + " (" + ErrorName(st.error) + ")";
}

std::string SettingsRefusalReason(NodeObjects& node) {
  uint32_t word = 0;
  if (!node.Read(ObjectId::kSettingsCheck, &word).ok) return "";
  const canopen::SettingsCheck c = canopen::DecodeSettingsCheck(word);
  if (c.finding.rule == ConfigRule::kNone) return "";
  const std::string axis =
      c.finding.axis != 0 ? "axis " + std::to_string(c.finding.axis) + ": " : std::string();
  return axis + ConfigRuleText(c.finding.rule);
}

SdoResult WithStagingReason(NodeObjects& node, SdoResult r) {
  if (r.ok || !r.aborted_by_server) return r;
  const std::string why = StagingFailureReason(node);
  if (!why.empty()) r.message += "; the board says: " + why;
  return r;
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

SdoResult WriteTableCommand(NodeObjects& node, TableCommand command) {
  SdoResult r = node.Write(ObjectId::kTableControl, canopen::Value(command));
  if (command == TableCommand::kVerify || command == TableCommand::kActivate) {
    r = WithStagingReason(node, r);
  }
  return Explain(r, TableCommandStep(command));
}

SdoResult EnsureWritable(NodeObjects& node) {
  uint32_t writable = 0;
  SdoResult r =
      Explain(node.Read(ObjectId::kWriteAccess, &writable), "reading write access (0x2111)");
  if (!r.ok || writable != 0) return r;
  return Explain(node.Write(ObjectId::kUnlock, canopen::kUnlockSignature), "unlocking (0x2110)");
}

SdoResult PrepareStaging(NodeObjects& node) {
  const SdoResult r = EnsureWritable(node);
  if (!r.ok) return r;
  return WriteTableCommand(node, TableCommand::kClear);
}

SdoResult VerifyStaged(NodeObjects& node, uint32_t image_crc, uint32_t* staged_crc) {
  SdoResult r = WriteTableCommand(node, TableCommand::kVerify);
  if (!r.ok) return r;
  uint32_t staged = 0;
  r = Explain(node.Read(ObjectId::kStagedTableCrc, &staged), "reading the staged CRC-32 (0x2105)");
  if (!r.ok) return r;
  if (staged_crc != nullptr) *staged_crc = staged;
  if (staged != image_crc) {
    r.ok = false;
    r.abort_code = canopen::SdoAbort::kNone;
    r.message = "the board staged CRC-32 " + Hex32(staged) + ", expected " + Hex32(image_crc);
  }
  return r;
}

}  // namespace volcomp::canopen_client
