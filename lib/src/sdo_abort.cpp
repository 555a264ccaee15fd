// SDO abort code texts.
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::canopen {

const char* SdoAbortText(uint32_t code) {
  switch (code) {
    case kAbortNone:
      return "no error";
    case kAbortToggle:
      return "toggle bit not alternated";
    case kAbortTimeout:
      return "SDO protocol timed out";
    case kAbortCommand:
      return "command specifier not valid or unknown";
    case kAbortBlockSize:
      return "invalid block size";
    case kAbortSequence:
      return "invalid sequence number";
    case kAbortCrc:
      return "CRC error (block mode)";
    case kAbortOutOfMemory:
      return "out of memory";
    case kAbortUnsupportedAccess:
      return "unsupported access to an object";
    case kAbortWriteOnly:
      return "attempt to read a write-only object";
    case kAbortReadOnly:
      return "attempt to write a read-only object";
    case kAbortNoObject:
      return "object does not exist in the object dictionary";
    case kAbortHardware:
      return "access failed due to a hardware error";
    case kAbortTypeMismatch:
      return "data type does not match, length does not match";
    case kAbortTooLong:
      return "data type does not match, length too high";
    case kAbortTooShort:
      return "data type does not match, length too low";
    case kAbortNoSubIndex:
      return "sub-index does not exist";
    case kAbortInvalidValue:
      return "invalid value for parameter";
    case kAbortValueTooHigh:
      return "value of parameter written too high";
    case kAbortValueTooLow:
      return "value of parameter written too low";
    case kAbortGeneral:
      return "general error";
    case kAbortCannotStore:
      return "data cannot be transferred or stored (write-protected)";
    case kAbortLocalControl:
      return "data cannot be transferred or stored because of local control";
    case kAbortDeviceState:
      return "not allowed in the present device state";
    case kAbortNoData:
      return "no data available";
    default:
      return "unknown abort code";
  }
}

}  // namespace volcomp::canopen
