// The PC tool's version: the one string `volcomp --version` prints and the reports state (the
// project version of CMakeLists.txt, compiled into version.cpp only).
#pragma once

namespace volcomp::cli {

/// "0.9.0" (without the program name).
const char* ToolVersion();

}  // namespace volcomp::cli
