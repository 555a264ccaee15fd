// CiA 301 SDO abort codes (section 7.2.4.3.17): the outcome of every object access below the
// command line. SdoAbort::kNone (0) means the access succeeded; any other value is the abort code
// the server sends (or the client received). Codes outside the named list (a client may abort
// with any value) are carried unchanged: an SdoAbort holds any 32-bit code.
#pragma once

#include <cstdint>

namespace volcomp::canopen {

enum class [[nodiscard]] SdoAbort : uint32_t{
    kNone = 0,
    kToggle = 0x05030000,             // toggle bit not alternated
    kTimeout = 0x05040000,            // SDO protocol timed out
    kCommand = 0x05040001,            // client/server command specifier not valid or unknown
    kBlockSize = 0x05040002,          // invalid block size (block mode)
    kSequence = 0x05040003,           // invalid sequence number (block mode)
    kCrc = 0x05040004,                // CRC error (block mode)
    kOutOfMemory = 0x05040005,        // out of memory
    kUnsupportedAccess = 0x06010000,  // unsupported access to an object
    kWriteOnly = 0x06010001,          // attempt to read a write-only object
    kReadOnly = 0x06010002,           // attempt to write a read-only object
    kNoObject = 0x06020000,           // object does not exist in the object dictionary
    kHardware = 0x06060000,           // access failed due to a hardware error
    kTypeMismatch = 0x06070010,       // data type does not match, length does not match
    kTooLong = 0x06070012,            // data type does not match, length too high
    kTooShort = 0x06070013,           // data type does not match, length too low
    kCannotMap = 0x06040041,          // object cannot be mapped to the PDO
    kPdoLength = 0x06040042,          // number and length of mapped objects exceed the PDO
    kNoSubIndex = 0x06090011,         // sub-index does not exist
    kInvalidValue = 0x06090030,       // invalid value for parameter (download only)
    kValueTooHigh = 0x06090031,       // value of parameter written too high
    kValueTooLow = 0x06090032,        // value of parameter written too low
    kGeneral = 0x08000000,            // general error
    kCannotStore = 0x08000020,        // data cannot be transferred or stored to the application
    kLocalControl = 0x08000021,       // ... because of local control
    kDeviceState = 0x08000022,        // ... because of the present device state
    kNoData = 0x08000024,             // no data available
};

/// Which side ended a transfer with an abort: the server (this node detected the failure: a
/// timeout, CRC, sequence or length error, a refusal) or the client (its abort frame: it reports
/// what the client saw, not something this node detected).
enum class AbortOrigin : uint8_t { kServer, kClient };

/// The code on the wire (bytes 4..7 of an abort frame, little-endian).
constexpr uint32_t Code(SdoAbort a) { return static_cast<uint32_t>(a); }
/// An abort code read from the wire.
constexpr SdoAbort AbortFromCode(uint32_t code) { return static_cast<SdoAbort>(code); }
/// True when `a` reports a failure (anything but kNone).
constexpr bool Failed(SdoAbort a) { return a != SdoAbort::kNone; }

/// True for the SDO protocol failures (0x0503xxxx toggle, 0x0504xxxx timeout, command, block size,
/// sequence, CRC, memory): the transfer broke, not the request, so a fresh attempt can succeed.
constexpr bool IsProtocolAbort(SdoAbort a) {
  return (Code(a) >> 16) == 0x0503 || (Code(a) >> 16) == 0x0504;
}

/// Readable text of an abort code ("unknown abort code" for others). Never null.
const char* SdoAbortText(SdoAbort a);

}  // namespace volcomp::canopen
