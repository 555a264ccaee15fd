// CiA 301 SDO frame protocol (section 7.2.4.3): the COB-IDs of the pre-defined connection set and
// byte 0 of every SDO frame (command specifier and flag bits), with the encoders and decoders the
// SDO server (lib) and the PC tool's SDO client both use. Pure functions on 8-byte frames. The bit
// layout of byte 0: docs/canopen.md, "Node" (frame layouts).
#pragma once

#include <cstdint>

namespace volcomp::canopen::sdo {

/// COB-IDs (+ node-ID): requests from the client, responses from the server.
inline constexpr uint32_t kRequestCobBase = 0x600;
inline constexpr uint32_t kResponseCobBase = 0x580;

/// Client command specifiers.
inline constexpr uint8_t kCcsDownloadSegment = 0;
inline constexpr uint8_t kCcsInitiateDownload = 1;
inline constexpr uint8_t kCcsInitiateUpload = 2;
inline constexpr uint8_t kCcsUploadSegment = 3;
inline constexpr uint8_t kCcsBlockUpload = 5;
inline constexpr uint8_t kCcsBlockDownload = 6;
/// Server command specifiers.
inline constexpr uint8_t kScsUploadSegment = 0;
inline constexpr uint8_t kScsDownloadSegment = 1;
inline constexpr uint8_t kScsInitiateUpload = 2;
inline constexpr uint8_t kScsInitiateDownload = 3;
inline constexpr uint8_t kScsBlockDownload = 5;
inline constexpr uint8_t kScsBlockUpload = 6;
/// Abort (either side).
inline constexpr uint8_t kCsAbort = 4;
inline constexpr uint8_t kAbort = kCsAbort << 5;

/// Block transfer sub-commands.
inline constexpr uint8_t kBlockInitiate = 0;
inline constexpr uint8_t kBlockEnd = 1;
inline constexpr uint8_t kBlockAck = 2;
inline constexpr uint8_t kBlockStartUpload = 3;

/// Flag bits.
inline constexpr uint8_t kSizeIndicated = 0x01;  // initiate: s
inline constexpr uint8_t kExpedited = 0x02;      // initiate: e
inline constexpr uint8_t kLastSegment = 0x01;    // segment: c
inline constexpr uint8_t kToggle = 0x10;         // segment and its acknowledgement: t
inline constexpr uint8_t kBlockCrc = 0x04;       // block initiate: cc / sc
inline constexpr uint8_t kBlockSizeIndicated = 0x02;
inline constexpr uint8_t kBlockLastSegment = 0x80;  // block segment: c
inline constexpr uint8_t kBlockSequenceMask = 0x7F;
inline constexpr uint8_t kMaxBlockSize = 127;
inline constexpr uint32_t kSegmentBytes = 7;

// ---- Decoding byte 0 ------------------------------------------------------------------------

constexpr uint8_t Specifier(uint8_t b0) { return static_cast<uint8_t>(b0 >> 5); }
constexpr uint8_t ToggleOf(uint8_t b0) { return static_cast<uint8_t>((b0 >> 4) & 1u); }
/// Data bytes of an expedited initiate (4 when the size is not indicated).
constexpr uint32_t ExpeditedBytes(uint8_t b0) {
  return (b0 & kSizeIndicated) != 0 ? 4u - ((b0 >> 2) & 0x03u) : 4u;
}
/// Data bytes of a download or upload segment.
constexpr uint32_t SegmentBytes(uint8_t b0) { return kSegmentBytes - ((b0 >> 1) & 0x07u); }
/// Unused bytes of the last block segment, from a block end frame.
constexpr uint32_t BlockEndUnused(uint8_t b0) { return (b0 >> 2) & 0x07u; }
constexpr uint8_t BlockSequence(uint8_t b0) { return b0 & kBlockSequenceMask; }

/// Client requests that start a transfer.
constexpr bool IsInitiateDownload(uint8_t b0) { return Specifier(b0) == kCcsInitiateDownload; }
constexpr bool IsInitiateUpload(uint8_t b0) { return Specifier(b0) == kCcsInitiateUpload; }
constexpr bool IsBlockDownloadInitiate(uint8_t b0) {
  return (b0 & 0xE1) == (kCcsBlockDownload << 5);
}
constexpr bool IsBlockUploadInitiate(uint8_t b0) { return (b0 & 0xE3) == (kCcsBlockUpload << 5); }
constexpr bool IsInitiate(uint8_t b0) {
  return IsInitiateDownload(b0) || IsInitiateUpload(b0) || IsBlockDownloadInitiate(b0) ||
         IsBlockUploadInitiate(b0);
}
/// The client's end of a block download (bit 1 reserved 0).
constexpr bool IsBlockDownloadEnd(uint8_t b0) {
  return (b0 & 0xE3) == ((kCcsBlockDownload << 5) | kBlockEnd);
}
/// The server's end of a block upload.
constexpr bool IsBlockUploadEnd(uint8_t b0) {
  return (b0 & 0xE3) == ((kScsBlockUpload << 5) | kBlockEnd);
}
/// The server's answer to a block download initiate (CRC bit ignored).
constexpr bool IsBlockDownloadInitiateResponse(uint8_t b0) {
  return (b0 & ~kBlockCrc & 0xFF) == (kScsBlockDownload << 5);
}
/// The server's answer to a block upload initiate (CRC and size bits ignored).
constexpr bool IsBlockUploadInitiateResponse(uint8_t b0) {
  return (b0 & 0xF9) == (kScsBlockUpload << 5);
}

// ---- Encoding byte 0 ------------------------------------------------------------------------

constexpr uint8_t Command(uint8_t specifier, uint8_t flags = 0) {
  return static_cast<uint8_t>((specifier << 5) | flags);
}
/// Initiate download request / initiate upload response: `bytes` 1..4 expedited, 0 = segmented.
constexpr uint8_t Initiate(uint8_t specifier, uint32_t expedited_bytes, bool size_indicated) {
  return expedited_bytes != 0
             ? Command(specifier, static_cast<uint8_t>(((4u - expedited_bytes) << 2) | kExpedited |
                                                       kSizeIndicated))
             : Command(specifier, size_indicated ? kSizeIndicated : 0);
}
/// A download or upload segment carrying `bytes` (1..7; 0 only for an empty last segment).
constexpr uint8_t Segment(uint8_t toggle, uint32_t bytes, bool last) {
  return static_cast<uint8_t>((toggle << 4) | ((kSegmentBytes - bytes) << 1) |
                              (last ? kLastSegment : 0));
}
/// A segment acknowledgement (download segment response, upload segment request).
constexpr uint8_t SegmentAck(uint8_t specifier, uint8_t toggle) {
  return Command(specifier, static_cast<uint8_t>(toggle << 4));
}
/// A block transfer command with sub-command `sub`.
constexpr uint8_t Block(uint8_t specifier, uint8_t sub, bool crc = false, bool size = false) {
  return Command(specifier, static_cast<uint8_t>((crc ? kBlockCrc : 0) |
                                                 (size ? kBlockSizeIndicated : 0) | sub));
}
/// The end of a block transfer whose last segment left `unused` bytes (0..6).
constexpr uint8_t BlockEndCommand(uint8_t specifier, uint32_t unused) {
  return Command(specifier, static_cast<uint8_t>((unused << 2) | kBlockEnd));
}
constexpr uint8_t BlockSegment(uint8_t sequence, bool last) {
  return static_cast<uint8_t>(sequence | (last ? kBlockLastSegment : 0));
}

}  // namespace volcomp::canopen::sdo
