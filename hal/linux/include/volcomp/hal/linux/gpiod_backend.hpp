// The libgpiod backend of the slow lines (libgpiod v1 API). Each configured line is requested once
// at Open(): inputs with their bias flag, outputs driven inactive; active-low is applied by the
// kernel, so levels are logical (no kernel debounce: LinuxSlowIo debounces). Built only with
// libgpiod-dev (VOLCOMP_HAVE_LIBGPIOD); otherwise MakeGpiodBackend() returns null and only the fake
// backend is accepted. Threading: one thread.
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
