// LinuxCNC RTAPI/HAL headers for a C++ uspace component. rtapi_app finds a module's entry points
// and parameters by their C names, so those are declared inside extern "C" by the including file.
#pragma once

#include <hal.h>
#include <rtapi.h>
#include <rtapi_app.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "volcomp/base/status.hpp"

namespace volcomp::linuxcnc {

/// Reads a whole file into `out`. kNotFound when it cannot be opened, kIoError when reading
/// fails; either is also reported through rtapi_print_msg naming `component` and `path`.
inline Status ReadFile(const char* component, const char* path, std::vector<uint8_t>* out) {
  FILE* f = std::fopen(path, "rb");
  if (f == nullptr) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: cannot open table image \"%s\"\n", component, path);
    return Error::kNotFound;
  }
  out->clear();
  uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out->insert(out->end(), buf, buf + n);
  const bool ok = std::ferror(f) == 0;
  std::fclose(f);
  if (!ok) {
    rtapi_print_msg(RTAPI_MSG_ERR, "%s: error reading \"%s\"\n", component, path);
    return Error::kIoError;
  }
  return Status::Ok();
}

}  // namespace volcomp::linuxcnc
