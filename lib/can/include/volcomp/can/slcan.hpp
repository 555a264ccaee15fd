// SLCAN (Lawicel ASCII) codec: frames and commands to lines, a byte stream to messages; the decoder
// is told its role (host or device: some letters mean a command one way and a response the
// other). Freestanding, bounded memory, safe on arbitrary input: a malformed or over-long line is
// a Kind::kMalformed message, never an over-read. Threading: a Decoder per byte stream and thread;
// the free functions are pure. The dialect: docs/can-transports.md, "SLCAN dialect".
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/can/can_frame.hpp"

namespace volcomp::slcan {

/// Longest legal line without its terminator: "T" + 8 id + 1 dlc + 16 data + 4 timestamp.
constexpr size_t kMaxLineLength = 30;
/// Buffer size that holds any encoded message including its terminator.
constexpr size_t kMaxEncodedLength = kMaxLineLength + 1;

/// Which side of the link the decoder sits on.
enum class Role : uint8_t {
  kDevice,  // decodes what a host sends: commands and frames to transmit
  kHost,    // decodes what a device sends: received frames and responses
};

enum class Kind : uint8_t {
  kFrame,  // t/T/r/R; `frame` (+ `has_timestamp`, `timestamp_ms`)
  // Commands (Role::kDevice).
  kOpen,            // O
  kListenOnly,      // L
  kClose,           // C
  kBitrate,         // Sn: `value` = n (0..9; see BitrateForIndex)
  kBtr,             // sxxyy: `value` = BTR0 << 8 | BTR1
  kStatusRequest,   // F
  kVersionRequest,  // V
  kDetailRequest,   // v
  kSerialRequest,   // N
  kTimestamps,      // Zn: `value` = 0 off, 1 on
  kAutoPoll,        // Xn: `value` = 0 off, 1 on
  kAcceptCode,      // Mxxxxxxxx: `value`
  kAcceptMask,      // mxxxxxxxx: `value`
  kUartRate,        // Un: `value` = n (0..9)
  kPollOne,         // P
  kPollAll,         // A
  // Responses (Role::kHost).
  kOk,            // "\r"
  kError,         // "\a"
  kTxAck,         // "z" (standard frame queued)
  kTxAckExt,      // "Z" (extended frame queued)
  kStatusReply,   // Fxx: `value` = status byte
  kVersionReply,  // Vxxxx: `text` = the 4 characters
  kDetailReply,   // vxxxx: `text`
  kSerialReply,   // Nxxxx: `text`
  // Neither.
  kMalformed,  // `error` says why
};

enum class ParseError : uint8_t {
  kNone,
  kLineTooLong,     // more than kMaxLineLength characters before the terminator
  kUnknownCommand,  // first character not known in this role
  kBadLength,       // wrong number of characters for the command
  kBadHex,          // a character that must be a hex digit is not
  kBadDlc,          // frame length character not '0'..'8'
  kIdOutOfRange,    // standard id > 0x7FF (3 digits allow 0xFFF) or extended id > 0x1FFFFFFF
  kBadArgument,     // argument outside its range (S/Z/X/U digit)
};

struct Message {
  Kind kind = Kind::kMalformed;
  ParseError error = ParseError::kNone;
  CanFrame frame;
  bool has_timestamp = false;
  uint16_t timestamp_ms = 0;  // 0..0xFFFF as sent (devices wrap at 60000)
  uint32_t value = 0;
  char text[5] = {};  // 4 characters + NUL for V/v/N replies
};

/// Bitrate in bit/s of the `Sn` index: 0..8 = 10k 20k 50k 100k 125k 250k 500k 800k 1M (Lawicel
/// and Linux slcan table), 9 = 83,333 (python-can's non-standard extension). 0 for other n.
uint32_t BitrateForIndex(uint32_t n);
/// The `Sn` index for a bitrate in bit/s, or -1 when the table has none (750000 has none: python-
/// can 4.1.0 sends S7 for it, which standard devices and this codec read as 800k).
int IndexForBitrate(uint32_t bitrate);

/// Writes `message` as one line with its terminator ('\r'; kError writes '\a' alone) into
/// out[0..capacity). Uppercase hex. Returns the number of bytes written, or 0 when the message is
/// not encodable (invalid frame, kMalformed, value out of range) or does not fit.
size_t Encode(const Message& message, char* out, size_t capacity);
/// Shorthand for Encode() of a kFrame message without timestamp.
size_t EncodeFrame(const CanFrame& frame, char* out, size_t capacity);

/// Parses one complete line (without terminator) in `role`. `length` may be anything; lines
/// longer than kMaxLineLength are kMalformed/kLineTooLong. An empty line is kOk.
Message ParseLine(Role role, const char* line, size_t length);

/// Incremental decoder: feed bytes one at a time.
///
/// Role::kDevice skips empty lines (the '\r's hosts send to flush a device); Role::kHost reports
/// an empty '\r' line as kOk and a '\a' (alone or ending a partial line) as kError. An over-long
/// line is discarded up to its terminator and reported once as kLineTooLong. NUL and '\n' bytes
/// are ignored (some terminals add them).
class Decoder {
 public:
  explicit Decoder(Role role) : role_(role) {}

  /// Consumes one byte; returns true and fills *out when it completed a message.
  bool Feed(uint8_t byte, Message* out);
  /// Drops any partial line.
  void Reset() {
    length_ = 0;
    overflow_ = false;
  }
  Role role() const { return role_; }

 private:
  Role role_;
  bool overflow_ = false;
  size_t length_ = 0;
  char line_[kMaxLineLength] = {};
};

}  // namespace volcomp::slcan
