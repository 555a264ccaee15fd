// Reading a table image file inside rtapi_app, for both components, with messages a LinuxCNC user
// can act on: the reason (errno's text), for a relative path the directory it is relative to, and
// for a file rtapi_app may not read the uid it runs as (RTAPI_UID or the invoking user) and the
// file's owner and mode. Outside the realtime threads only (loadrt, the native loader thread).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/base/status.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::linuxcnc {

/// The whole file at `path`: kNotFound (no such file), kIoError (any other reason to fail), or
/// kImageTooLarge (larger than an image may be), each with the whole message.
Expected<std::vector<uint8_t>> ReadTableFile(const std::string& path);

/// `table "PATH" refused: invalid table image: TEXT (NAME)`, the words of `volcomp inspect`.
std::string ImageRefusal(const std::string& path, Status status);

}  // namespace volcomp::linuxcnc
