// The identity strings of the node (0x1008 device name, 0x1009 hardware version, 0x100A software
// version): one definition for the firmware, the simulator, the Linux board and the EDS writer.
// 0x1009 names the hardware the node runs on, so it is the one identity value that differs
// between the board and its stand-ins; the EDS declares it read-only (not const), gives the
// board's value as its default and lists the others in its [Comments] (docs/canopen.md, "Node").
#pragma once

#include <cstddef>
#include <cstdint>

namespace volcomp::canopen {

inline constexpr const char* kDeviceNameText = "volcomp";     // 0x1008
inline constexpr const char* kSoftwareVersionText = "0.1.0";  // 0x100A

/// What the firmware runs on (0x1009).
enum class Hardware : uint8_t {
  kBoard = 0,       // the volcomp board (STM32G474), hardware revision 1.0: the EDS default
  kLinuxBoard = 1,  // volcomp-fw-linux on a Linux board (docs/linux-board.md)
  kSimulator = 2,   // volcomp-sim node and the host tests (the mock HAL)
  kCount = 3,
};

inline constexpr const char* kHardwareVersions[] = {"1.0", "linux", "simulator"};
static_assert(sizeof(kHardwareVersions) / sizeof(kHardwareVersions[0]) ==
                  static_cast<size_t>(Hardware::kCount),
              "one 0x1009 string per hardware");

/// The 0x1009 string of `h`.
constexpr const char* HardwareVersion(Hardware h) {
  return kHardwareVersions[static_cast<uint8_t>(h) < static_cast<uint8_t>(Hardware::kCount)
                               ? static_cast<uint8_t>(h)
                               : 0];
}

}  // namespace volcomp::canopen
