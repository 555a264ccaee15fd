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
  /// with the abort code that ended it and who sent it (`origin`: the server's own abort for a
  /// CRC, size or timeout failure, or the client's abort frame with whatever code it chose).
  /// After a failed transfer the implementation must discard what it received; code and origin
  /// tell it why (for its diagnostics). The return value of a failed transfer's EndDomainWrite is
  /// ignored.
  SdoAbort BeginDomainWrite(const ObjectEntry& e, uint32_t size) {
    return DoBeginDomainWrite(e, size);
  }
  SdoAbort DomainWriteData(const uint8_t* data, uint32_t size) {
    return DoDomainWriteData(data, size);
  }
  SdoAbort EndDomainWrite(SdoAbort outcome, AbortOrigin origin = AbortOrigin::kServer) {
    return DoEndDomainWrite(outcome, origin);
  }
  /// Flow control of a DOMAIN write whose data takes time to make durable (flash): the most bytes
  /// DomainWriteData() accepts between two complete flushes without doing that slow work itself
  /// (0 = no limit: the value needs no pacing). Asked once per block download, after
  /// BeginDomainWrite: the SDO server sizes its sub-blocks to it.
  uint32_t DomainWriteWindow() { return DoDomainWriteWindow(); }
  /// Does a bounded part of the slow work for the bytes delivered so far; `*done` = true once none
  /// is left. The SDO server calls it from its Poll() before each block acknowledgement of a
  /// paced transfer (the client sends nothing until then). A failure aborts the transfer.
  SdoAbort DomainWriteFlush(bool* done) { return DoDomainWriteFlush(done); }

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
  virtual SdoAbort DoEndDomainWrite(SdoAbort outcome, AbortOrigin origin) = 0;
  virtual uint32_t DoDomainWriteWindow() { return 0; }
  virtual SdoAbort DoDomainWriteFlush(bool* done) {
    *done = true;
    return SdoAbort::kNone;
  }
};

}  // namespace volcomp::canopen
