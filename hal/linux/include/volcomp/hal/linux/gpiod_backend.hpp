// The libgpiod backend of the slow lines (Debian bookworm: libgpiod 1.6.3, v1 API, kernel GPIO
// character device uAPI v1). Each configured line is requested once at Open(): inputs with their
// bias flag, outputs driven inactive; active-low is applied by the kernel, so levels are logical.
// libgpiod 1.6 has no debounce: LinuxSlowIo debounces in software.
//
// Built only when libgpiod-dev is found (VOLCOMP_HAVE_LIBGPIOD); MakeGpiodBackend() returns null
// otherwise, and the firmware then accepts only the fake backend.
//
// Thread-safety: one thread.
#pragma once

#include <memory>
#include <string>

#include "volcomp/hal/linux/gpio_lines.hpp"

namespace volcomp::hal::linux_board {

/// A new libgpiod backend, or null when this build has no libgpiod.
std::unique_ptr<GpioBackend> MakeGpiodBackend();
/// True when this build has the libgpiod backend.
bool HaveLibgpiod();

}  // namespace volcomp::hal::linux_board
