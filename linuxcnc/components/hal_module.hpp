// LinuxCNC RTAPI/HAL headers for a C++ uspace component. rtapi_app finds a module's entry points
// and parameters by their C names, so those are declared inside extern "C" by the including file.
#pragma once

#include <hal.h>
#include <rtapi.h>
#include <rtapi_app.h>
