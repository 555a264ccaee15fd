// SDO abort code texts.
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::canopen {

const char* SdoAbortText(SdoAbort a) {
  switch (a) {
    case SdoAbort::kNone:
      return "no error";
    case SdoAbort::kToggle:
      return "toggle bit not alternated";
    case SdoAbort::kTimeout:
      return "SDO protocol timed out";
    case SdoAbort::kCommand:
      return "command specifier not valid or unknown";
    case SdoAbort::kBlockSize:
      return "invalid block size";
    case SdoAbort::kSequence:
      return "invalid sequence number";
    case SdoAbort::kCrc:
      return "CRC error (block mode)";
    case SdoAbort::kOutOfMemory:
      return "out of memory";
    case SdoAbort::kUnsupportedAccess:
      return "unsupported access to an object";
    case SdoAbort::kWriteOnly:
      return "attempt to read a write-only object";
    case SdoAbort::kReadOnly:
      return "attempt to write a read-only object";
    case SdoAbort::kNoObject:
      return "object does not exist in the object dictionary";
    case SdoAbort::kHardware:
      return "access failed due to a hardware error";
    case SdoAbort::kTypeMismatch:
      return "data type does not match, length does not match";
    case SdoAbort::kTooLong:
      return "data type does not match, length too high";
    case SdoAbort::kTooShort:
      return "data type does not match, length too low";
    case SdoAbort::kCannotMap:
      return "object cannot be mapped to the PDO";
    case SdoAbort::kPdoLength:
      return "number and length of mapped objects exceed the PDO length";
    case SdoAbort::kNoSubIndex:
      return "sub-index does not exist";
    case SdoAbort::kInvalidValue:
      return "invalid value for parameter";
    case SdoAbort::kValueTooHigh:
      return "value of parameter written too high";
    case SdoAbort::kValueTooLow:
      return "value of parameter written too low";
    case SdoAbort::kGeneral:
      return "general error";
    case SdoAbort::kCannotStore:
      return "data cannot be transferred or stored to the application";
    case SdoAbort::kLocalControl:
      return "data cannot be transferred or stored because of local control";
    case SdoAbort::kDeviceState:
      return "not allowed in the present device state";
    case SdoAbort::kNoData:
      return "no data available";
    default:
      return "unknown abort code";
  }
}

}  // namespace volcomp::canopen
