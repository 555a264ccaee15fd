// The PC tool's table transfer, run against the simulated board in virtual time with the PC tool's
// own protocol code (tools/canopen: NodeObjects, the staging steps of table_staging.hpp, SdoClient
// through sdo_runner), in the same order as `volcomp upload` (tools/cli/cmd_upload.cpp): read
// the active CRC-32 and the bank size, PrepareStaging (unlock if needed, clear the staging bank),
// block-download the image into 0x2100, VerifyStaged (verify on the board, compare the staged
// CRC-32); then activation (0x2101 = 1) and a check of the active CRC-32 (0x2104) and device
// state (0x2122). Failures (an SDO abort, a refused activation) come back with the PC tool's
// explanation of the abort.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/sim/world.hpp"

namespace volcomp::sim {

struct UploadReport {
  uint32_t bytes = 0;
  uint32_t image_crc = 0;
  uint32_t staged_crc = 0;
  double transfer_s = 0;  // block download, virtual time
  double rate_bytes_s = 0;
  uint64_t frames = 0;
  uint32_t resent_segments = 0;
};

/// Stages and verifies `image` on the board; progress lines go to `log`. Fails with kIoError (an
/// SDO transfer failed, the reason names the object) or kImageTooLarge (the bank is smaller).
Expected<UploadReport> UploadTable(World& world,
                                   const std::vector<uint8_t>& image,
                                   std::ostream& log);

struct ActivationReport {
  uint32_t active_crc = 0;
  uint16_t device_state = 0;  // 0x2122 after activation
};

/// Activates the staged table. Fails with kIoError (the board refused: SDO abort, e.g. not
/// referenced) or kImageBadCrc (the active CRC-32 is not `expected_crc`).
Expected<ActivationReport> ActivateTable(World& world, uint32_t expected_crc);

/// Reads 0x2122 (device state bits, canopen/board_protocol.hpp DeviceStateBit).
uint16_t ReadDeviceState(World& world);

}  // namespace volcomp::sim
