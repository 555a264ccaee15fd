// The application side of the object dictionary: object values. The SDO server checks existence,
// type and access against kObjectEntries before it calls these; implementations only produce or
// accept values. Every call returns 0 or a CiA 301 SDO abort code (sdo_abort.hpp), which the
// server sends to the client unchanged.
#pragma once

#include <cstdint>

#include "volcomp/canopen/object_dictionary.hpp"

namespace volcomp::canopen {

class ObjectValues {
 public:
  /// Copies up to `cap` bytes of the value of `e`, starting at byte `offset`, into `buf`;
  /// `*copied` = bytes copied, `*total` = size of the whole value (for strings and domains the
  /// current length; for fixed-size types FixedSize()).
  uint32_t Read(const ObjectEntry& e,
                uint32_t offset,
                uint8_t* buf,
                uint32_t cap,
                uint32_t* copied,
                uint32_t* total) {
    return DoRead(e, offset, buf, cap, copied, total);
  }
  /// Writes a whole value of a fixed-size or string object (`size` bytes, little-endian).
  uint32_t Write(const ObjectEntry& e, const uint8_t* data, uint32_t size) {
    return DoWrite(e, data, size);
  }
  /// Streams a DOMAIN write: BeginDomainWrite (size 0 = not indicated), DomainWriteData in order,
  /// then EndDomainWrite(true) on success or EndDomainWrite(false) when the transfer failed or was
  /// aborted (the implementation must then discard what it received).
  uint32_t BeginDomainWrite(const ObjectEntry& e, uint32_t size) {
    return DoBeginDomainWrite(e, size);
  }
  uint32_t DomainWriteData(const uint8_t* data, uint32_t size) {
    return DoDomainWriteData(data, size);
  }
  uint32_t EndDomainWrite(bool complete) { return DoEndDomainWrite(complete); }

 protected:
  ~ObjectValues() = default;

 private:
  virtual uint32_t DoRead(const ObjectEntry& e,
                          uint32_t offset,
                          uint8_t* buf,
                          uint32_t cap,
                          uint32_t* copied,
                          uint32_t* total) = 0;
  virtual uint32_t DoWrite(const ObjectEntry& e, const uint8_t* data, uint32_t size) = 0;
  virtual uint32_t DoBeginDomainWrite(const ObjectEntry& e, uint32_t size) = 0;
  virtual uint32_t DoDomainWriteData(const uint8_t* data, uint32_t size) = 0;
  virtual uint32_t DoEndDomainWrite(bool complete) = 0;
};

}  // namespace volcomp::canopen
