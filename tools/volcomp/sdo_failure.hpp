// How the CAN commands turn a failed SDO access into an error for the user.
#pragma once

#include <string>

#include "volcomp/canopen/sdo_abort.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {

/// A failed SDO access; `retryable` when a fresh attempt can succeed (protocol errors, timeouts).
class SdoFailure : public InputError {
 public:
  SdoFailure(const std::string& message, canopen::SdoAbort abort_code)
      : InputError(message), retryable(canopen::IsProtocolAbort(abort_code)) {}
  bool retryable;
};

/// Throws SdoFailure when `r` failed (its message already says which step and why).
inline void Require(const canopen_client::SdoResult& r) {
  if (!r.ok) throw SdoFailure(r.message, r.abort_code);
}

/// Throws SdoFailure when `r` failed, naming `step` and what to do about the common refusals.
inline void Check(const canopen_client::SdoResult& r, const std::string& step) {
  Require(canopen_client::Explain(r, step));
}

}  // namespace volcomp::tools
