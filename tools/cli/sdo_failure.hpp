// How the CAN commands turn a failed SDO access into an error for the user.
#pragma once

#include <string>

#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"

namespace volcomp::tools {

/// A failed SDO access; `retryable` when a fresh attempt can succeed (protocol errors, timeouts).
class SdoFailure : public InputError {
 public:
  SdoFailure(const std::string& message, canopen::SdoAbort abort_code)
      : InputError(message), retryable(canopen::IsProtocolAbort(abort_code)) {}
  bool retryable;
};

/// True when `r` failed because nothing answered in time: the board is absent, off or not on
/// this bus (a communication failure, exit 3), not a refusal.
inline bool NoAnswer(const canopen_client::SdoResult& r) {
  return !r.ok && !r.aborted_by_server && r.abort_code == canopen::SdoAbort::kTimeout;
}

/// Throws when `r` failed (its message already says which step and why): CommunicationError when
/// nothing answered, else SdoFailure.
inline void Require(const canopen_client::SdoResult& r) {
  if (NoAnswer(r)) throw CommunicationError(r.message);
  if (!r.ok) throw SdoFailure(r.message, r.abort_code);
}

/// Throws SdoFailure when `r` failed, naming `step` and what to do about the common refusals.
inline void Check(const canopen_client::SdoResult& r, const std::string& step) {
  Require(canopen_client::Explain(r, step));
}

}  // namespace volcomp::tools
