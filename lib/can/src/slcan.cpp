// SLCAN codec: line encoder, line parser and the byte-at-a-time decoder around it.
#include "volcomp/can/slcan.hpp"

namespace volcomp::slcan {
namespace {

constexpr char kHexDigits[] = "0123456789ABCDEF";
constexpr uint32_t kBitrates[] = {10000,  20000,  50000,  100000,  125000,
                                  250000, 500000, 800000, 1000000, 83333};
constexpr uint32_t kBitrateCount = sizeof kBitrates / sizeof kBitrates[0];

// Value of a hex digit (either case), or -1.
int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// Parses `count` (<= 8) hex digits at `p`; false when one is not a hex digit.
bool ParseHex(const char* p, size_t count, uint32_t* value) {
  uint32_t v = 0;
  for (size_t i = 0; i < count; ++i) {
    const int d = HexValue(p[i]);
    if (d < 0) return false;
    v = (v << 4) | static_cast<uint32_t>(d);
  }
  *value = v;
  return true;
}

Message Malformed(ParseError error) {
  Message m;
  m.kind = Kind::kMalformed;
  m.error = error;
  return m;
}

Message Simple(Kind kind, uint32_t value = 0) {
  Message m;
  m.kind = kind;
  m.value = value;
  return m;
}

// t/T/r/R lines: id, length digit, data (not for RTR), optional 4-digit timestamp.
Message ParseFrame(const char* line, size_t length) {
  const char type = line[0];
  const bool extended = type == 'T' || type == 'R';
  const bool rtr = type == 'r' || type == 'R';
  const size_t id_digits = extended ? 8 : 3;
  if (length < 1 + id_digits + 1) return Malformed(ParseError::kBadLength);
  Message m;
  m.kind = Kind::kFrame;
  CanFrame& f = m.frame;
  f.extended = extended;
  f.rtr = rtr;
  if (!ParseHex(line + 1, id_digits, &f.id)) return Malformed(ParseError::kBadHex);
  if (f.id > (extended ? 0x1FFFFFFFu : 0x7FFu)) return Malformed(ParseError::kIdOutOfRange);
  const char dlc_char = line[1 + id_digits];
  if (dlc_char < '0' || dlc_char > '8') return Malformed(ParseError::kBadDlc);
  f.dlc = static_cast<uint8_t>(dlc_char - '0');
  size_t pos = 2 + id_digits;
  const size_t data_digits = rtr ? 0 : 2u * f.dlc;
  const size_t rest = length - pos;
  if (rest != data_digits && rest != data_digits + 4) return Malformed(ParseError::kBadLength);
  for (uint8_t i = 0; i < f.dlc && !rtr; ++i, pos += 2) {
    uint32_t byte = 0;
    if (!ParseHex(line + pos, 2, &byte)) return Malformed(ParseError::kBadHex);
    f.data[i] = static_cast<uint8_t>(byte);
  }
  if (rest == data_digits + 4) {
    uint32_t ts = 0;
    if (!ParseHex(line + pos, 4, &ts)) return Malformed(ParseError::kBadHex);
    m.has_timestamp = true;
    m.timestamp_ms = static_cast<uint16_t>(ts);
  }
  return m;
}

// A command letter followed by exactly `digits` hex digits.
Message ParseHexArgument(Kind kind, const char* line, size_t length, size_t digits) {
  if (length != 1 + digits) return Malformed(ParseError::kBadLength);
  uint32_t value = 0;
  if (!ParseHex(line + 1, digits, &value)) return Malformed(ParseError::kBadHex);
  return Simple(kind, value);
}

// A command letter followed by one decimal digit in 0..max.
Message ParseDigitArgument(Kind kind, const char* line, size_t length, char max) {
  if (length != 2) return Malformed(ParseError::kBadLength);
  if (line[1] < '0' || line[1] > max) return Malformed(ParseError::kBadArgument);
  return Simple(kind, static_cast<uint32_t>(line[1] - '0'));
}

// A command letter with no argument.
Message ParseBare(Kind kind, size_t length) {
  return length == 1 ? Simple(kind) : Malformed(ParseError::kBadLength);
}

// A reply letter followed by 4 printable characters (version and serial strings are not
// guaranteed to be hex on every adapter).
Message ParseText(Kind kind, const char* line, size_t length) {
  if (length != 5) return Malformed(ParseError::kBadLength);
  Message m = Simple(kind);
  for (size_t i = 0; i < 4; ++i) {
    const char c = line[1 + i];
    if (c < 0x21 || c > 0x7E) return Malformed(ParseError::kBadArgument);
    m.text[i] = c;
  }
  return m;
}

Message ParseCommand(const char* line, size_t length) {
  switch (line[0]) {
    case 'O':
      return ParseBare(Kind::kOpen, length);
    case 'L':
      return ParseBare(Kind::kListenOnly, length);
    case 'C':
      return ParseBare(Kind::kClose, length);
    case 'F':
      return ParseBare(Kind::kStatusRequest, length);
    case 'V':
      return ParseBare(Kind::kVersionRequest, length);
    case 'v':
      return ParseBare(Kind::kDetailRequest, length);
    case 'N':
      return ParseBare(Kind::kSerialRequest, length);
    case 'P':
      return ParseBare(Kind::kPollOne, length);
    case 'A':
      return ParseBare(Kind::kPollAll, length);
    case 'S':
      return ParseDigitArgument(Kind::kBitrate, line, length, '9');
    case 'Z':
      return ParseDigitArgument(Kind::kTimestamps, line, length, '1');
    case 'X':
      return ParseDigitArgument(Kind::kAutoPoll, line, length, '1');
    case 'U':
      return ParseDigitArgument(Kind::kUartRate, line, length, '9');
    case 's':
      return ParseHexArgument(Kind::kBtr, line, length, 4);
    case 'M':
      return ParseHexArgument(Kind::kAcceptCode, line, length, 8);
    case 'm':
      return ParseHexArgument(Kind::kAcceptMask, line, length, 8);
    default:
      return Malformed(ParseError::kUnknownCommand);
  }
}

Message ParseResponse(const char* line, size_t length) {
  switch (line[0]) {
    case 'z':
      return ParseBare(Kind::kTxAck, length);
    case 'Z':
      return ParseBare(Kind::kTxAckExt, length);
    case 'F':
      return ParseHexArgument(Kind::kStatusReply, line, length, 2);
    case 'V':
      return ParseText(Kind::kVersionReply, line, length);
    case 'v':
      return ParseText(Kind::kDetailReply, line, length);
    case 'N':
      return ParseText(Kind::kSerialReply, line, length);
    default:
      return Malformed(ParseError::kUnknownCommand);
  }
}

// Bounded writer into the caller's buffer; `ok()` false once anything did not fit.
class Writer {
 public:
  Writer(char* out, size_t capacity) : out_(out), capacity_(capacity) {}
  void Put(char c) {
    if (size_ < capacity_) {
      out_[size_++] = c;
    } else {
      overflow_ = true;
    }
  }
  void Hex(uint32_t value, unsigned digits) {
    for (unsigned i = digits; i-- > 0;) Put(kHexDigits[(value >> (4 * i)) & 0xFu]);
  }
  size_t Finish() { return overflow_ ? 0 : size_; }

 private:
  char* out_;
  size_t capacity_;
  size_t size_ = 0;
  bool overflow_ = false;
};

bool EncodeFrameBody(const Message& m, Writer* w) {
  const CanFrame& f = m.frame;
  if (!f.valid()) return false;
  w->Put(f.extended ? (f.rtr ? 'R' : 'T') : (f.rtr ? 'r' : 't'));
  w->Hex(f.id, f.extended ? 8 : 3);
  w->Put(static_cast<char>('0' + f.dlc));
  for (uint8_t i = 0; i < f.dlc && !f.rtr; ++i) w->Hex(f.data[i], 2);
  if (m.has_timestamp) w->Hex(m.timestamp_ms, 4);
  return true;
}

bool EncodeText(char letter, const Message& m, Writer* w) {
  w->Put(letter);
  for (size_t i = 0; i < 4; ++i) {
    const char c = m.text[i];
    if (c < 0x21 || c > 0x7E) return false;
    w->Put(c);
  }
  return true;
}

// Letter + one decimal digit in 0..max.
bool EncodeDigit(char letter, uint32_t value, uint32_t max, Writer* w) {
  if (value > max) return false;
  w->Put(letter);
  w->Put(static_cast<char>('0' + value));
  return true;
}

bool EncodeHexArgument(char letter, uint32_t value, unsigned digits, Writer* w) {
  if (digits < 8 && (value >> (4 * digits)) != 0) return false;
  w->Put(letter);
  w->Hex(value, digits);
  return true;
}

// Everything before the terminator; false when the message has no encoding.
bool EncodeBody(const Message& m, Writer* w) {
  switch (m.kind) {
    case Kind::kFrame:
      return EncodeFrameBody(m, w);
    case Kind::kOpen:
      w->Put('O');
      return true;
    case Kind::kListenOnly:
      w->Put('L');
      return true;
    case Kind::kClose:
      w->Put('C');
      return true;
    case Kind::kBitrate:
      return EncodeDigit('S', m.value, 9, w);
    case Kind::kBtr:
      return EncodeHexArgument('s', m.value, 4, w);
    case Kind::kStatusRequest:
      w->Put('F');
      return true;
    case Kind::kVersionRequest:
      w->Put('V');
      return true;
    case Kind::kDetailRequest:
      w->Put('v');
      return true;
    case Kind::kSerialRequest:
      w->Put('N');
      return true;
    case Kind::kTimestamps:
      return EncodeDigit('Z', m.value, 1, w);
    case Kind::kAutoPoll:
      return EncodeDigit('X', m.value, 1, w);
    case Kind::kAcceptCode:
      return EncodeHexArgument('M', m.value, 8, w);
    case Kind::kAcceptMask:
      return EncodeHexArgument('m', m.value, 8, w);
    case Kind::kUartRate:
      return EncodeDigit('U', m.value, 9, w);
    case Kind::kPollOne:
      w->Put('P');
      return true;
    case Kind::kPollAll:
      w->Put('A');
      return true;
    case Kind::kOk:
      return true;
    case Kind::kError:
      return true;  // the terminator is the message
    case Kind::kTxAck:
      w->Put('z');
      return true;
    case Kind::kTxAckExt:
      w->Put('Z');
      return true;
    case Kind::kStatusReply:
      return EncodeHexArgument('F', m.value, 2, w);
    case Kind::kVersionReply:
      return EncodeText('V', m, w);
    case Kind::kDetailReply:
      return EncodeText('v', m, w);
    case Kind::kSerialReply:
      return EncodeText('N', m, w);
    case Kind::kMalformed:
      return false;
  }
  return false;
}

}  // namespace

uint32_t BitrateForIndex(uint32_t n) { return n < kBitrateCount ? kBitrates[n] : 0; }

int IndexForBitrate(uint32_t bitrate) {
  for (uint32_t i = 0; i < kBitrateCount; ++i) {
    if (kBitrates[i] == bitrate) return static_cast<int>(i);
  }
  return -1;
}

size_t Encode(const Message& message, char* out, size_t capacity) {
  if (out == nullptr) return 0;
  Writer w(out, capacity);
  if (!EncodeBody(message, &w)) return 0;
  w.Put(message.kind == Kind::kError ? '\a' : '\r');
  return w.Finish();
}

size_t EncodeFrame(const CanFrame& frame, char* out, size_t capacity) {
  Message m;
  m.kind = Kind::kFrame;
  m.frame = frame;
  return Encode(m, out, capacity);
}

Message ParseLine(Role role, const char* line, size_t length) {
  if (length > kMaxLineLength) return Malformed(ParseError::kLineTooLong);
  if (length == 0) return Simple(Kind::kOk);
  switch (line[0]) {
    case 't':
    case 'T':
    case 'r':
    case 'R':
      return ParseFrame(line, length);
    default:
      break;
  }
  // "Z" alone from a device is an ack; "Z1" from a host a command (handled by the role split).
  return role == Role::kDevice ? ParseCommand(line, length) : ParseResponse(line, length);
}

bool Decoder::Feed(uint8_t byte, Message* out) {
  const char c = static_cast<char>(byte);
  if (c == '\0' || c == '\n') return false;
  if (c != '\r' && c != '\a') {
    if (overflow_) return false;
    if (length_ == kMaxLineLength) {
      overflow_ = true;  // keep discarding until the terminator
      return false;
    }
    line_[length_++] = c;
    return false;
  }
  // A terminator.
  const bool overflow = overflow_;
  const size_t length = length_;
  Reset();
  if (overflow) {
    *out = Malformed(ParseError::kLineTooLong);
    return true;
  }
  if (role_ == Role::kHost && c == '\a') {
    *out = Simple(Kind::kError);
    return true;
  }
  if (length == 0 && role_ == Role::kDevice) return false;  // flush '\r's and stray BELs
  *out = ParseLine(role_, line_, length);
  return true;
}

}  // namespace volcomp::slcan
