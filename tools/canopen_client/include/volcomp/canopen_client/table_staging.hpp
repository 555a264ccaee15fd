// The board's table-staging protocol as one sequence of object accesses, shared by the PC tool
// (`volcomp upload`) and the simulator's demo session, so both exercise the same steps:
//
//   PrepareStaging: read write access (0x2111), unlock (0x2110 = "unlk") if it is off, clear the
//                   staging bank (0x2101 = 3);
//   (the caller writes the image into 0x2100 by block transfer, with its own progress and timing);
//   VerifyStaged:   verify on the board (0x2101 = 4), read the staged CRC-32 (0x2105) and compare
//                   it with the image's.
//
// Every failure is an SdoFailure whose message names the step and explains the common refusals
// (see Explain()); its abort is the server's (kNone, code kImageBadCrc, for a CRC mismatch).
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::canopen_client {

/// What to do about the board's common refusals (write-protected, not referenced / moving, nothing
/// staged); empty for other codes.
std::string AbortHint(canopen::SdoAbort abort_code);
/// What a refused verification (0x2101 = 4) means: 0x08000020 the staged image fails the board's
/// checks, 0x08000022 an upload is in progress, 0x08000024 nothing complete is staged.
std::string VerifyHint(canopen::SdoAbort abort_code);

/// `f` with its message prefixed by `step` and followed by what to do ("step: reason; hint").
SdoFailure Explain(SdoFailure f, const std::string& step);
/// `r` explained by `step` when it failed; unchanged if ok.
template <typename T>
SdoExpected<T> Explain(SdoExpected<T> r, const std::string& step) {
  if (r.ok()) return r;
  return Fail(Explain(r.error(), step));
}

/// The board's own reason for a failed staging step (a refused verification, activation or
/// transfer), from its table status (0x2102): the error of the last staging failure in words
/// ("image was built for another units-per-step (kConfigResolutionMismatch)"), "nothing is staged"
/// for an empty bank, or empty when neither applies or 0x2102 cannot be read.
std::string StagingFailureReason(NodeObjects& node);

/// The board's reason for refusing to store its settings (0x1010), from 0x2123: the rule the
/// pending settings break and its axis ("axis 2: max input rate ... must not exceed ..."), or
/// empty when they break none or 0x2123 cannot be read.
std::string SettingsRefusalReason(NodeObjects& node);
/// The rule the board's pending settings break and its axis (0x2123), kNone when they break none
/// or 0x2123 cannot be read.
ConfigFinding SettingsFinding(NodeObjects& node);

/// `f` with the board's reason appended when the board refused (by_server) and its staging bank
/// says why (StagingFailureReason); unchanged otherwise.
SdoFailure WithStagingReason(NodeObjects& node, SdoFailure f);
template <typename T>
SdoExpected<T> WithStagingReason(NodeObjects& node, SdoExpected<T> r) {
  if (r.ok()) return r;
  return Fail(WithStagingReason(node, r.error()));
}

/// What writing `command` to table control does, with the write: "activating (0x2101 = 1)".
std::string TableCommandStep(canopen::TableCommand command);

/// Writes `command` to table control (0x2101); a failure is Explain()ed with TableCommandStep(),
/// a refused verification or activation also WithStagingReason().
SdoOutcome WriteTableCommand(NodeObjects& node, canopen::TableCommand command);

/// Reads write access (0x2111) and unlocks the board (0x2110) if it is off: before every write to
/// tables or settings (staging, activation, deactivation).
SdoOutcome EnsureWritable(NodeObjects& node);

/// EnsureWritable(), then clears the staging bank.
SdoOutcome PrepareStaging(NodeObjects& node);

/// Verifies the staged image on the board and checks its CRC-32 (then equal to `image_crc`);
/// another CRC-32 is a failure naming both (kImageBadCrc, no abort).
SdoOutcome VerifyStaged(NodeObjects& node, uint32_t image_crc);

}  // namespace volcomp::canopen_client
