// The board's table-staging protocol as one sequence of object accesses, shared by the PC tool
// (`volcomp upload`) and the simulator's demo session, so both exercise the same steps:
//
//   PrepareStaging: read write access (0x2111), unlock (0x2110 = "unlk") if it is off, clear the
//                   staging bank (0x2101 = 3);
//   (the caller block-downloads the image into 0x2100, with its own progress and timing);
//   VerifyStaged:   verify on the board (0x2101 = 4), read the staged CRC-32 (0x2105) and compare
//                   it with the image's.
//
// Every failure comes back as an SdoResult whose message names the step and explains the common
// refusals (see Explain()); abort_code is the server's (kNone for a CRC mismatch).
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/node_objects.hpp"

namespace volcomp::canopen_client {

/// What to do about the board's common refusals (write-protected, not referenced / moving, nothing
/// staged); empty for other codes.
std::string AbortHint(canopen::SdoAbort abort_code);

/// `r` with its message prefixed by `step` ("step: reason; hint") when it failed; unchanged if ok.
SdoResult Explain(SdoResult r, const std::string& step);

/// The board's own reason for a failed staging step (a refused verification, activation or
/// transfer), from its table status (0x2102): the error of the last staging failure in words
/// ("image was built for another units-per-step (kConfigResolutionMismatch)"), "nothing is staged"
/// for an empty bank, or empty when neither applies or 0x2102 cannot be read.
std::string StagingFailureReason(NodeObjects& node);

/// The board's reason for refusing to store its settings (0x1010), from 0x2123: the rule the
/// pending settings break and its axis ("axis 2: max input rate ... must not exceed ..."), or
/// empty when they break none or 0x2123 cannot be read.
std::string SettingsRefusalReason(NodeObjects& node);

/// `r` with the board's reason appended when the board refused (aborted_by_server) and its staging
/// bank says why (StagingFailureReason); unchanged otherwise.
SdoResult WithStagingReason(NodeObjects& node, SdoResult r);

/// What writing `command` to table control does, with the write: "activating (0x2101 = 1)".
std::string TableCommandStep(canopen::TableCommand command);

/// Writes `command` to table control (0x2101); a failure is Explain()ed with TableCommandStep(),
/// a refused verification or activation also WithStagingReason().
SdoResult WriteTableCommand(NodeObjects& node, canopen::TableCommand command);

/// Reads write access (0x2111) and unlocks the board (0x2110) if it is off: before every write to
/// tables or settings (staging, activation, deactivation).
SdoResult EnsureWritable(NodeObjects& node);

/// EnsureWritable(), then clears the staging bank.
SdoResult PrepareStaging(NodeObjects& node);

/// Verifies the staged image on the board and checks its CRC-32 against `image_crc`;
/// `*staged_crc` (optional) receives the board's value when it could be read.
SdoResult VerifyStaged(NodeObjects& node, uint32_t image_crc, uint32_t* staged_crc = nullptr);

}  // namespace volcomp::canopen_client
