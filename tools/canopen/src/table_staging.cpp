// The table-staging steps.
#include "volcomp/canopen_client/table_staging.hpp"

#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::canopen_client {

using canopen::ObjectId;
using tools::Hex32;

std::string AbortHint(uint32_t abort_code) {
  switch (abort_code) {
    case canopen::kAbortCannotStore:
      return "the board is write-protected: set its write-enable input or let the tool unlock it";
    case canopen::kAbortDeviceState:
      return "the axes must be referenced (homed) and at rest";
    case canopen::kAbortNoData:
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
  return Explain(node.Write(ObjectId::kTableControl, 3), "clearing the staging bank (0x2101 = 3)");
}

SdoResult VerifyStaged(NodeObjects& node, uint32_t image_crc, uint32_t* staged_crc) {
  SdoResult r =
      Explain(node.Write(ObjectId::kTableControl, 4), "verifying on the board (0x2101 = 4)");
  if (!r.ok) return r;
  uint32_t staged = 0;
  r = Explain(node.Read(ObjectId::kStagedTableCrc, &staged), "reading the staged CRC-32 (0x2105)");
  if (!r.ok) return r;
  if (staged_crc != nullptr) *staged_crc = staged;
  if (staged != image_crc) {
    r.ok = false;
    r.abort_code = 0;
    r.message = "the board staged CRC-32 " + Hex32(staged) + ", expected " + Hex32(image_crc);
  }
  return r;
}

}  // namespace volcomp::canopen_client
