// The PC tool's version (VOLCOMP_VERSION comes from tools/CMakeLists.txt).
#include "version.hpp"

namespace volcomp::cli {

const char* ToolVersion() { return VOLCOMP_VERSION; }

}  // namespace volcomp::cli
