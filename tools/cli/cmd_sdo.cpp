// `volcomp sdo read|write INDEX:SUB [VALUE]`: raw object access.
//
// A write is checked against the object dictionary before anything is sent (value_check.hpp: the
// object exists and is writable, the value is an integer within its type and limits) and sent in
// the size of its type. When the board refuses, its reason is added: the rule the settings break
// for a store (0x1010, from 0x2123), the staging error for table objects (from 0x2102).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <ostream>

#include "can_options.hpp"
#include "commands.hpp"
#include "sdo_failure.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/canopen_client/table_staging.hpp"
#include "volcomp/canopen_client/value_check.hpp"

namespace volcomp::cli {
namespace {

using canopen::ObjectId;
using canopen::TableCommand;

struct Address {
  uint16_t index = 0;
  uint8_t sub = 0;
};

// The number at the start of `text` in `base` (0: decimal, 0x-hex or 0-octal), as strtoul reads
// it; nullopt when there is none or it is too large.
std::optional<unsigned long> LeadingNumber(const std::string& text, int base) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const unsigned long v = std::strtoul(begin, &end, base);
  if (end == begin || errno == ERANGE) return std::nullopt;
  return v;
}

// "INDEX:SUB", INDEX in hex, SUB in decimal or 0x-hex (":SUB" optional: 0).
Expected<Address> ParseAddress(const std::string& text) {
  const size_t colon = text.find(':');
  const auto index = LeadingNumber(text.substr(0, colon), 16);
  const auto sub = colon == std::string::npos ? std::optional<unsigned long>(0)
                                              : LeadingNumber(text.substr(colon + 1), 0);
  if (!index || !sub || *index > 0xFFFF || *sub > 0xFF) {
    return UsageFailure("object address \"" + text + "\": use INDEX:SUB in hex, e.g. 2104:0");
  }
  return Address{static_cast<uint16_t>(*index), static_cast<uint8_t>(*sub)};
}

// A value read, as `sdo read` prints it: text objects as text, up to 4 bytes as a number (signed
// for the INTEGER16/32 objects) with its hex, longer values as hex bytes.
JsonValue ReadData(const std::string& object,
                   const canopen::ObjectEntry* e,
                   const std::vector<uint8_t>& data) {
  JsonValue d = JsonValue::Object();
  d.Set("object", object);
  if (e != nullptr && e->type == canopen::DataType::kVisibleString) {
    d.Set("form", "text");
    d.Set("value", std::string(data.begin(), data.end()));
  } else if (data.size() <= 4) {
    uint32_t v = 0;
    for (size_t i = 0; i < data.size(); ++i) v |= uint32_t{data[i]} << (8 * i);
    const bool is_signed = e != nullptr && (e->type == canopen::DataType::kInteger32 ||
                                            e->type == canopen::DataType::kInteger16);
    d.Set("form", is_signed ? "signed" : "unsigned");
    d.Set("value", is_signed ? JsonValue(int64_t{static_cast<int32_t>(v)}) : JsonValue(v));
    d.Set("raw", v);
  } else {
    std::string hex;
    char b[3];
    for (const uint8_t byte : data) {
      std::snprintf(b, sizeof b, "%02X", byte);
      hex += b;
    }
    d.Set("form", "bytes");
    d.Set("value", hex);
  }
  return d;
}

void ReadText(const JsonValue& d, std::ostream& out) {
  const std::string& form = d.get("form")->string;
  const JsonValue& value = *d.get("value");
  if (form == "text" || form == "bytes") {
    out << value.string << "\n";
    return;
  }
  char line[48];
  const auto raw = static_cast<unsigned>(d.get("raw")->integer);
  if (form == "signed") {
    std::snprintf(line, sizeof line, "%d (0x%X)\n", static_cast<int>(value.integer), raw);
  } else {
    std::snprintf(line, sizeof line, "%u (0x%X)\n", raw, raw);
  }
  out << line;
}

void WriteText(const JsonValue&, std::ostream& out) { out << "ok\n"; }

Expected<Output> Read(const CanConnection& can, const std::string& object, Address a) {
  VOLCOMP_TRY_ASSIGN(const auto s, OpenSession(can));
  VOLCOMP_TRY_ASSIGN(const std::vector<uint8_t> data,
                     Required(canopen_client::ReadObject(s->link(), can.node, a.index, a.sub, false,
                                                         s->options())));
  return Output{ReadData(object, canopen::FindEntry(a.index, a.sub), data), ReadText, {}};
}

// The board's reason for refusing a write to `a` (a store, a staging step), "" when it has none.
std::string RefusalReason(canopen_client::NodeObjects& node,
                          Address a,
                          const std::vector<uint8_t>& payload) {
  if (a.index == canopen::Entry(ObjectId::kStoreAll).index) {
    return canopen_client::SettingsRefusalReason(node);
  }
  const bool staging_step = (a.index == canopen::Entry(ObjectId::kTableControl).index &&
                             (payload[0] == canopen::Value(TableCommand::kVerify) ||
                              payload[0] == canopen::Value(TableCommand::kActivate))) ||
                            a.index == canopen::Entry(ObjectId::kTableData).index;
  return staging_step ? canopen_client::StagingFailureReason(node) : std::string();
}

Expected<Output> Write(const CanConnection& can,
                       const std::string& object,
                       Address a,
                       const std::string& value) {
  const canopen::ObjectEntry* e = canopen::FindEntry(a.index, a.sub);
  if (e == nullptr) {
    return UsageFailure("object " + object +
                        " is not in the dictionary (docs/volcomp.eds lists them)");
  }
  const Expected<std::vector<uint8_t>> payload = canopen_client::EncodeWriteValue(*e, value);
  if (!payload.ok()) {
    return UsageFailure("cannot write " + object + ": " + payload.error().message +
                        "; nothing was sent");
  }
  VOLCOMP_TRY_ASSIGN(const auto s, OpenSession(can));
  canopen_client::SdoOutcome written =
      canopen_client::WriteObject(s->link(), can.node, a.index, a.sub, *payload, s->options());
  if (!written.ok() && written.error().by_server) {
    const std::string reason = RefusalReason(*s, a, *payload);
    if (!reason.empty()) {
      canopen_client::SdoFailure f = written.error();
      f.message += "; the board says: " + reason;
      written = Fail(std::move(f));
    }
  }
  VOLCOMP_TRY(Checked(std::move(written), "writing " + object));
  JsonValue d = JsonValue::Object();
  d.Set("object", object);
  d.Set("value", value);
  return Output{std::move(d), WriteText, {}};
}

Expected<Output> RunSdo(Args& args, Context&) {
  VOLCOMP_TRY_ASSIGN(const CanConnection can, ParseCanOptions(args));
  const auto words = args.Positionals();
  VOLCOMP_TRY(args.Finish());
  if (words.size() < 2 || (words[0] != "read" && words[0] != "write")) {
    return UsageFailure("expected `read INDEX:SUB` or `write INDEX:SUB VALUE`");
  }
  VOLCOMP_TRY_ASSIGN(const Address a, ParseAddress(words[1]));
  if (words[0] == "read") {
    if (words.size() != 2) return UsageFailure("read takes no VALUE");
    return Read(can, words[1], a);
  }
  if (words.size() != 3) return UsageFailure("write needs a VALUE");
  return Write(can, words[1], a, words[2]);
}

}  // namespace

const Command& SdoCommand() {
  static const Command kCommand{
      "sdo",
      "read or write one object: sdo read 2104:0, sdo write 2018:1 -5000",
      "read|write INDEX:SUB [VALUE]",
      CanOptions(),
      RunSdo,
      "INDEX in hex, SUB in decimal or 0x-hex; VALUE an integer (decimal, 0x-hex, negative).\n"
      "A negative VALUE is a value, not an option; `--` before it also works.\n"
      "A write is checked against the object dictionary before anything is sent: the object\n"
      "must be writable and VALUE within its type and limits (exit 2 otherwise). When the\n"
      "board refuses, its reason is printed (for a store, the rule and the axis)."};
  return kCommand;
}

}  // namespace volcomp::cli
