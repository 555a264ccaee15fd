// candump -L log writer and reader.
#include "volcomp/can_io/candump_log.hpp"

#include <cstdio>
#include <istream>

namespace volcomp::can_io {
namespace {

int Hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

bool ParseDecimal(const std::string& s, uint64_t* value) {
  if (s.empty() || s.size() > 19) return false;
  uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<uint64_t>(c - '0');
  }
  *value = v;
  return true;
}

Unexpected<Failure> Malformed(const std::string& why) { return Fail(Error::kInputInvalid, why); }

// "123#11223344", "12345678#", "123#R", "123#R8"; a malformed frame says why.
Expected<CanFrame> ParseFrame(const std::string& text) {
  const size_t hash = text.find('#');
  if (hash == std::string::npos) return Malformed("no '#' in frame '" + text + "'");
  const std::string id = text.substr(0, hash);
  const std::string data = text.substr(hash + 1);
  if (id.size() != 3 && id.size() != 8) {
    return Malformed("id '" + id + "' must have 3 (standard) or 8 (extended) hex digits");
  }
  if (!data.empty() && data[0] == '#') return Malformed("CAN FD frames are not supported");
  CanFrame f;
  f.extended = id.size() == 8;
  for (char c : id) {
    const int d = Hex(c);
    if (d < 0) return Malformed("id '" + id + "' is not hex");
    f.id = (f.id << 4) | static_cast<uint32_t>(d);
  }
  if (!f.valid()) return Malformed("id '" + id + "' out of range");
  if (!data.empty() && (data[0] == 'R' || data[0] == 'r')) {
    f.rtr = true;
    if (data.size() == 2 && data[1] >= '0' && data[1] <= '8') {
      f.dlc = static_cast<uint8_t>(data[1] - '0');
    } else if (data.size() != 1) {
      return Malformed("bad remote frame '" + text + "'");
    }
    return f;
  }
  // Data bytes, optionally separated by '.' (can-utils accepts "11.22.33").
  std::string hex;
  for (char c : data) {
    if (c != '.') hex += c;
  }
  if (hex.size() % 2 != 0 || hex.size() > 16)
    return Malformed("data '" + data + "' must be 0..8 whole bytes");
  for (size_t i = 0; i < hex.size(); i += 2) {
    const int hi = Hex(hex[i]);
    const int lo = Hex(hex[i + 1]);
    if (hi < 0 || lo < 0) return Malformed("data '" + data + "' is not hex");
    f.data[i / 2] = static_cast<uint8_t>(hi << 4 | lo);
  }
  f.dlc = static_cast<uint8_t>(hex.size() / 2);
  return f;
}

}  // namespace

std::string FormatCandumpLine(const CandumpRecord& r) {
  char head[48];
  std::snprintf(head, sizeof head, "(%llu.%06llu) ",
                static_cast<unsigned long long>(r.timestamp_us / 1000000),
                static_cast<unsigned long long>(r.timestamp_us % 1000000));
  std::string line = head + r.iface + " ";
  char id[16];
  std::snprintf(id, sizeof id, r.frame.extended ? "%08X#" : "%03X#",
                static_cast<unsigned>(r.frame.id));
  line += id;
  if (r.frame.rtr) {
    line += 'R';
    if (r.frame.dlc != 0) line += static_cast<char>('0' + (r.frame.dlc > 8 ? 8 : r.frame.dlc));
  } else {
    static const char kHex[] = "0123456789ABCDEF";
    for (uint8_t i = 0; i < r.frame.dlc && i < 8; ++i) {
      line += kHex[r.frame.data[i] >> 4];
      line += kHex[r.frame.data[i] & 0xF];
    }
  }
  if (r.direction == Direction::kTx) line += " T";
  if (r.direction == Direction::kRx) line += " R";
  return line;
}

Expected<CandumpRecord> ParseCandumpLine(const std::string& raw) {
  std::string line = raw;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  // Fields separated by single or multiple spaces.
  std::vector<std::string> fields;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && line[i] == ' ') ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  if (fields.size() < 3 || fields.size() > 4) {
    return Malformed("expected '(SEC.USEC) IFACE FRAME [T|R]'");
  }
  const std::string& ts = fields[0];
  const size_t dot = ts.find('.');
  if (ts.size() < 4 || ts.front() != '(' || ts.back() != ')' || dot == std::string::npos) {
    return Malformed("timestamp '" + ts + "' is not (SEC.USEC)");
  }
  uint64_t sec = 0;
  uint64_t usec = 0;
  const std::string frac = ts.substr(dot + 1, ts.size() - dot - 2);
  if (!ParseDecimal(ts.substr(1, dot - 1), &sec) || frac.size() != 6 ||
      !ParseDecimal(frac, &usec)) {
    return Malformed("timestamp '" + ts + "' is not (SEC.USEC) with 6 fraction digits");
  }
  CandumpRecord r;
  r.timestamp_us = sec * 1000000 + usec;
  r.iface = fields[1];
  VOLCOMP_TRY_ASSIGN(r.frame, ParseFrame(fields[2]));
  if (fields.size() == 4) {
    if (fields[3] == "T") {
      r.direction = Direction::kTx;
    } else if (fields[3] == "R") {
      r.direction = Direction::kRx;
    } else {
      return Malformed("direction '" + fields[3] + "' is not T or R");
    }
  }
  return r;
}

Expected<std::vector<CandumpRecord>> ReadCandumpLog(std::istream& in) {
  std::vector<CandumpRecord> out;
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    Expected<CandumpRecord> r = ParseCandumpLine(line);
    if (!r.ok()) return Fail(r.error().Prefixed("line " + std::to_string(number)));
    out.push_back(std::move(r).value());
  }
  return out;
}

CandumpLogWriter::CandumpLogWriter(std::ostream& out, std::string iface, bool direction_markers)
    : out_(&out), iface_(std::move(iface)), direction_markers_(direction_markers) {}

Expected<std::unique_ptr<CandumpLogWriter>> CandumpLogWriter::OpenFile(const std::string& path,
                                                                       std::string iface,
                                                                       bool direction_markers) {
  auto file = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc);
  if (!*file) return Fail(Error::kIoError, "cannot write CAN log '" + path + "'");
  auto writer = std::make_unique<CandumpLogWriter>(*file, std::move(iface), direction_markers);
  writer->file_ = std::move(file);
  return writer;
}

void CandumpLogWriter::Write(const CanFrame& frame, Direction direction) {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  Write(frame, direction,
        static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(now).count()));
}

void CandumpLogWriter::Write(const CanFrame& frame, Direction direction, uint64_t timestamp_us) {
  CandumpRecord r;
  r.timestamp_us = timestamp_us;
  r.iface = iface_;
  r.frame = frame;
  r.direction = direction_markers_ ? direction : Direction::kNone;
  *out_ << FormatCandumpLine(r) << '\n';
  out_->flush();
  ++lines_;
}

}  // namespace volcomp::can_io
