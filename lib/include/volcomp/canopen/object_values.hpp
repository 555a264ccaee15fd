// The application side of the object dictionary: object values. The SDO server checks existence,
// type and access against kObjectEntries before it calls these; implementations only produce or
// accept values. Every call returns SdoAbort::kNone or the CiA 301 abort code (sdo_abort.hpp) the
// server sends to the client unchanged.
#pragma once

#include <cstdint>

#include "volcomp/canopen/object_dictionary.hpp"
#include "volcomp/canopen/sdo_abort.hpp"

namespace volcomp::canopen {

class ObjectValues {
 public:
  /// Copies up to `cap` bytes of the value of `e`, starting at byte `offset`, into `buf`;
  /// `*copied` = bytes copied, `*total` = size of the whole value (for strings and domains the
  /// current length; for fixed-size types FixedSize()).
  SdoAbort Read(const ObjectEntry& e,
                uint32_t offset,
                uint8_t* buf,
                uint32_t cap,
                uint32_t* copied,
                uint32_t* total) {
    return DoRead(e, offset, buf, cap, copied, total);
  }
  /// Writes a whole value of a fixed-size or string object (`size` bytes, little-endian).
  SdoAbort Write(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
    return DoWrite(e, data, size);
  }
  /// Streams a DOMAIN write: BeginDomainWrite (size 0 = not indicated), DomainWriteData in order,
  /// then EndDomainWrite(SdoAbort::kNone) when the transfer completed, or EndDomainWrite(code)
  /// with the abort code that ended it (sent by the server: CRC, size, timeout, ...; or received
  /// from the client). After a failed transfer the implementation must discard what it received;
  /// the code tells it why (for its diagnostics). The return value of a failed transfer's
  /// EndDomainWrite is ignored.
  SdoAbort BeginDomainWrite(const ObjectEntry& e, uint32_t size) {
    return DoBeginDomainWrite(e, size);
  }
  SdoAbort DomainWriteData(const uint8_t* data, uint32_t size) {
    return DoDomainWriteData(data, size);
  }
  SdoAbort EndDomainWrite(SdoAbort outcome) { return DoEndDomainWrite(outcome); }

 protected:
  ~ObjectValues() = default;

 private:
  virtual SdoAbort DoRead(const ObjectEntry& e,
                          uint32_t offset,
                          uint8_t* buf,
                          uint32_t cap,
                          uint32_t* copied,
                          uint32_t* total) = 0;
  virtual SdoAbort DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) = 0;
  virtual SdoAbort DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) = 0;
  virtual SdoAbort DoDomainWriteData(const uint8_t* data, uint32_t size) = 0;
  virtual SdoAbort DoEndDomainWrite(SdoAbort outcome) = 0;
};

}  // namespace volcomp::canopen
