// CiA 301 SDO abort codes (the subset volcomp sends or recognises), with readable texts.
#pragma once

#include <cstdint>

namespace volcomp::canopen {

enum SdoAbort : uint32_t {
  kAbortNone = 0,
  kAbortToggle = 0x05030000,             // toggle bit not alternated
  kAbortTimeout = 0x05040000,            // SDO protocol timed out
  kAbortCommand = 0x05040001,            // client/server command specifier not valid or unknown
  kAbortBlockSize = 0x05040002,          // invalid block size (block mode)
  kAbortSequence = 0x05040003,           // invalid sequence number (block mode)
  kAbortCrc = 0x05040004,                // CRC error (block mode)
  kAbortOutOfMemory = 0x05040005,        // out of memory
  kAbortUnsupportedAccess = 0x06010000,  // unsupported access to an object
  kAbortWriteOnly = 0x06010001,          // attempt to read a write-only object
  kAbortReadOnly = 0x06010002,           // attempt to write a read-only object
  kAbortNoObject = 0x06020000,           // object does not exist in the object dictionary
  kAbortHardware = 0x06060000,           // access failed due to a hardware error
  kAbortTypeMismatch = 0x06070010,       // data type does not match, length does not match
  kAbortTooLong = 0x06070012,            // data type does not match, length too high
  kAbortTooShort = 0x06070013,           // data type does not match, length too low
  kAbortNoSubIndex = 0x06090011,         // sub-index does not exist
  kAbortInvalidValue = 0x06090030,       // invalid value for parameter (download only)
  kAbortValueTooHigh = 0x06090031,       // value of parameter written too high
  kAbortValueTooLow = 0x06090032,        // value of parameter written too low
  kAbortGeneral = 0x08000000,            // general error
  kAbortCannotStore = 0x08000020,        // data cannot be transferred or stored to the application
  kAbortLocalControl = 0x08000021,       // ... because of local control
  kAbortDeviceState = 0x08000022,        // ... because of the present device state
  kAbortNoData = 0x08000024,             // no data available
};

/// True for the SDO protocol failures (0x0503xxxx toggle, 0x0504xxxx timeout, command, block size,
/// sequence, CRC, memory): the transfer broke, not the request, so a fresh attempt can succeed.
constexpr bool IsProtocolAbort(uint32_t code) {
  return (code >> 16) == 0x0503 || (code >> 16) == 0x0504;
}

/// Readable text of an abort code ("unknown abort code" for others). Never null.
const char* SdoAbortText(uint32_t code);

}  // namespace volcomp::canopen
