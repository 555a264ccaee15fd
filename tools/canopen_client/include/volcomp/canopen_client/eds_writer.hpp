// Writes the CiA 306 EDS (electronic data sheet) of a volcomp node from the shared object
// dictionary definition (od_entries.def). The checked-in docs/volcomp.eds is this output; a test
// regenerates it and fails when they differ, so firmware, PC tool and EDS cannot drift apart.
#pragma once

#include <ostream>
#include <string>

#include "volcomp/canopen/identity.hpp"

namespace volcomp::canopen_client {

struct EdsInfo {
  std::string file_name = "volcomp.eds";
  std::string vendor_name = "volcomp project";
  std::string product_name = "volcomp volumetric compensation co-processor";
  std::string device_name = canopen::kDeviceNameText;  // 0x1008 default
  // 0x1009 default (the board's); the other hardware's values go to [Comments]
  std::string hardware_version = canopen::HardwareVersion(canopen::Hardware::kBoard);
  std::string software_version = canopen::kSoftwareVersionText;  // 0x100A default
};

void WriteEds(std::ostream& out, const EdsInfo& info = EdsInfo());

}  // namespace volcomp::canopen_client
