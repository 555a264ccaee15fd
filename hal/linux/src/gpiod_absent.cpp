// Built instead of gpiod_backend.cpp when libgpiod-dev is not installed: no libgpiod backend.
#include "volcomp/hal/linux/gpiod_backend.hpp"

namespace volcomp::hal::linux_board {

std::unique_ptr<GpioBackend> MakeGpiodBackend() { return nullptr; }
bool HaveLibgpiod() { return false; }

}  // namespace volcomp::hal::linux_board
